// Per-patch Ceres problems with augmented-Lagrangian DOG constraints, and their parallel solve.
#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include "solver/patches/ceres/ceres_patch_solver.h"
#include "tests/solver/patch_case.h"

namespace sdog {
namespace {

using test::PatchCase;

// One Ceres solver per patch of the case.
std::vector<std::unique_ptr<PatchStepper>> ceres_solvers(const PatchCase& c) {
  std::vector<std::unique_ptr<PatchStepper>> out;
  for (int p = 0; p < c.model.fine.patch_count(); ++p)
    out.push_back(std::make_unique<CeresPatchSolver>(c.model.fine, p, c.problem->objective_terms(),
                                                     c.problem->dog));
  return out;
}

TEST(CeresPatchSolver, LowersThePatchObjectiveAndMeetsTheConstraintTolerance) {
  const PatchCase s("four_corner_arcs.svg", {15, 15});
  Dofs x = s.bent();
  const Dofs x0 = x;
  // The last patch holds the dragged corner: its objective is far from its minimum.
  CeresPatchSolver last(s.model.fine, s.model.fine.patch_count() - 1, s.problem->objective_terms(),
                        s.problem->dog);
  const double before = last.objective(x);
  const PatchReport r = last.solve(x);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.dog_max, 5e-5);
  EXPECT_NEAR(r.dog_max, last.dog_max(x), 1e-15);
  EXPECT_LT(r.objective, 0.5 * before);
  EXPECT_DOUBLE_EQ(r.objective, last.objective(x));
  EXPECT_GE(r.outer, 1);
  EXPECT_GE(r.work.steps, 1);
  // Only the patch's own vertices moved.
  const int begin = s.model.fine.patch_begin[last.patch()],
            end = s.model.fine.patch_begin[last.patch() + 1];
  for (int v = 0; v < s.model.fine.vertex_count(); ++v) {
    const bool moved = (vertex_of(x, v) - vertex_of(x0, v)).norm() > 0;
    if (v < begin || v >= end) {
      EXPECT_FALSE(moved) << "vertex " << v << " outside the patch moved";
    }
  }
}

TEST(CeresPatchSolver, ParallelSolveEqualsSerialSolve) {
  const PatchCase s("four_corner_arcs.svg", {15, 15});
  Dofs serial = s.bent(), parallel = serial;
  std::vector<PatchReport> a, b;
  {
    auto solvers = ceres_solvers(s);
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    a = step_patches(solvers, serial, false);
  }
  {
    auto solvers = ceres_solvers(s);
    tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
    b = step_patches(solvers, parallel, false);
  }
  EXPECT_TRUE(serial == parallel);
  ASSERT_EQ(a.size(), static_cast<size_t>(s.model.fine.patch_count()));
  for (size_t p = 0; p < a.size(); ++p) {
    EXPECT_EQ(a[p].patch, static_cast<int>(p));
    EXPECT_TRUE(a[p].converged) << "patch " << p << " dog_max " << a[p].dog_max;
    EXPECT_EQ(a[p].objective, b[p].objective);
    EXPECT_GT(a[p].ms, 0);
  }
}

TEST(CeresPatchSolver, WarmStartStaysFeasibleAndDoesNotClimb) {
  const PatchCase s("one_curve.svg", {15, 11});
  auto solvers = ceres_solvers(s);
  Dofs x = s.bent();
  const auto first = step_patches(solvers, x, false);
  const auto again = step_patches(solvers, x, false);
  for (size_t p = 0; p < again.size(); ++p) {
    EXPECT_TRUE(again[p].converged) << "patch " << p;
    // Patches without position targets may slide rigidly (bending and isometry do not see it);
    // the objective may only go down.
    EXPECT_LE(again[p].objective, first[p].objective * (1 + 1e-6) + 1e-9) << "patch " << p;
  }
}

TEST(CeresPatchSolver, WeightChangesReachTheCeresProblem) {
  const PatchCase s("one_curve.svg", {15, 11});
  CeresPatchSolver solver(s.model.fine, s.model.fine.patch_count() - 1,
                          s.problem->objective_terms(), s.problem->dog);
  Dofs x = s.bent();
  const double before = solver.objective(x);
  solver.set_weight(kPositions, 0);
  EXPECT_LT(solver.objective(x), before);  // the position term carried weight before
}

}  // namespace
}  // namespace sdog
