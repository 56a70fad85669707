// A patch stepped by the SQP solver on its own blocks (patch_sqp.h).
#include <gtest/gtest.h>

#include "solver/patches/ceres/ceres_patch_solver.h"  // its objective and residual, for reference
#include "solver/patches/patch_sqp.h"
#include "tests/solver/patch_case.h"

namespace sdog {
namespace {

using test::PatchCase;

TEST(PatchSqp, StepsOnlyItsPatchAndMeetsTheTolerance) {
  const PatchCase s("four_corner_arcs.svg", {15, 15});
  const int patch = s.model.fine.patch_count() - 1;
  PatchSqp sqp(s.model.fine, patch, s.problem->objective_terms(), s.problem->dog, SqpOptions{});
  CeresPatchSolver reference(s.model.fine, patch, s.problem->objective_terms(), s.problem->dog);
  Dofs x = s.bent();
  const Dofs x0 = x;
  const double before = reference.objective(x);
  for (int k = 0; k < 5; ++k) {
    const PatchReport r = sqp.step(x, k == 4);
    ASSERT_TRUE(r.converged);
    EXPECT_LE(reference.dog_max(x), 5e-5 * 1.01) << "step " << k;
  }
  EXPECT_LE(reference.dog_max(x), 1e-6);
  EXPECT_LT(reference.objective(x), 0.5 * before);
  const int begin = s.model.fine.patch_begin[patch], end = s.model.fine.patch_begin[patch + 1];
  for (int v = 0; v < s.model.fine.vertex_count(); ++v)
    if (v < begin || v >= end) {
      EXPECT_EQ(vertex_of(x, v), vertex_of(x0, v)) << "vertex " << v;
    }
}

}  // namespace
}  // namespace sdog
