// Per-patch Ceres problems with augmented-Lagrangian DOG constraints, and their parallel solve.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "geometry/dog_model.h"
#include "solver/problem/dog_problem.h"
#include "solver/patches/ceres/ceres_patch_solver.h"
#include "solver/patches/patch_sqp.h"
#include "solver/patches/patch_term.h"
#include "solver/problem/scenario.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

struct PatchCase {
  DogModel model;
  std::unique_ptr<DogProblem> problem;
  Scenario scenario;
  explicit PatchCase(const std::string& pattern, Eigen::Vector2i res) {
    model = build_dog_model(read_crease_pattern(test::dataset(pattern)), {res[0], res[1]});
    problem = std::make_unique<DogProblem>(model.fine, model.fine_topology);
    scenario = corners_scenario(model.fine, 10, 0);
    scenario.install(*problem);
    scenario.apply(*problem, 0.5);  // the dragged corner half way
  }
  std::vector<std::unique_ptr<PatchStepper>> solvers() const {
    std::vector<std::unique_ptr<PatchStepper>> out;
    for (int p = 0; p < model.fine.patch_count(); ++p)
      out.push_back(std::make_unique<CeresPatchSolver>(model.fine, p, problem->objective_terms(), problem->dog));
    return out;
  }
  // A bent start: the flat sheet rolled around the y axis (a developable state, DOG constraints 0).
  Dofs bent() const {
    Dofs x = to_dofs(model.fine.V);
    const double radius = 3 * model.fine.nx();
    for (Eigen::Index v = 0; v < x.size() / 3; ++v) {
      const double a = x[3 * v] / radius;
      x[3 * v] = radius * std::sin(a);
      x[3 * v + 2] = radius * (1 - std::cos(a));
    }
    return x;
  }
};

TEST(CeresPatchSolver, LowersThePatchObjectiveAndMeetsTheConstraintTolerance) {
  const PatchCase s("four_corner_arcs.svg", {15, 15});
  Dofs x = s.bent();
  const Dofs x0 = x;
  // The last patch holds the dragged corner: its objective is far from its minimum.
  CeresPatchSolver last(s.model.fine, s.model.fine.patch_count() - 1, s.problem->objective_terms(), s.problem->dog);
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
  const int begin = s.model.fine.patch_begin[last.patch()], end = s.model.fine.patch_begin[last.patch() + 1];
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
    auto solvers = s.solvers();
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    a = step_patches(solvers, serial, false);
  }
  {
    auto solvers = s.solvers();
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
  auto solvers = s.solvers();
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
  CeresPatchSolver solver(s.model.fine, s.model.fine.patch_count() - 1, s.problem->objective_terms(), s.problem->dog);
  Dofs x = s.bent();
  const double before = solver.objective(x);
  solver.set_weight(kPositions, 0);
  EXPECT_LT(solver.objective(x), before);  // the position term carried weight before
}

TEST(PatchTerm, KeepsTheBlocksInsideThePatchReindexed) {
  const PatchCase s("four_corner_arcs.svg", {15, 15});
  const DogMesh& mesh = s.model.fine;
  const Term& dog = s.problem->dog;
  const Dofs x = s.bent();
  int total = 0;
  for (int p = 0; p < mesh.patch_count(); ++p) {
    const int begin = mesh.patch_begin[p], end = mesh.patch_begin[p + 1];
    const PatchTerm view(dog, begin, end);
    total += view.block_count();
    for (int b = 0; b < view.block_count(); ++b) {
      const int src = view.source_block(b);
      ASSERT_EQ(view.block_size(b), dog.block_size(src));
      std::vector<Eigen::Vector3d> p1(view.block_size(b));
      for (int j = 0; j < view.block_size(b); ++j) {
        const int v = view.block_vertices(b)[j];
        ASSERT_GE(v, 0);
        ASSERT_LT(v, end - begin);
        ASSERT_EQ(v + begin, dog.block_vertices(src)[j]);
        p1[j] = vertex_of(x, v + begin);
      }
      Eigen::VectorXd r1(view.residual_count(b)), r2(view.residual_count(b));
      view.evaluate(b, p1.data(), r1.data(), nullptr);
      dog.evaluate(src, p1.data(), r2.data(), nullptr);
      EXPECT_EQ(r1, r2);
    }
  }
  EXPECT_EQ(total, dog.block_count());  // DOG constraints never cross patches
}

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

TEST(TermCost, OffsetShiftsResidualsNotJacobians) {
  const PatchCase s("one_curve.svg", {15, 11});
  const Term& dog = s.problem->dog;
  const Dofs x = s.bent() + 0.01 * Dofs::Ones(s.bent().size());
  const int b = 0, k = dog.block_size(b), m = dog.residual_count(b);
  std::vector<double> offset(m);
  for (int i = 0; i < m; ++i) offset[i] = 0.1 * (i + 1);
  TermCost plain(dog, b, 4.0), shifted(dog, b, 4.0, offset.data());
  std::vector<const double*> params;
  for (int j = 0; j < k; ++j) params.push_back(x.data() + 3 * dog.block_vertices(b)[j]);
  std::vector<double> r1(m), r2(m), J1(3 * m * k), J2(3 * m * k);
  std::vector<double*> j1, j2;
  for (int j = 0; j < k; ++j) {
    j1.push_back(J1.data() + 3 * m * j);
    j2.push_back(J2.data() + 3 * m * j);
  }
  ASSERT_TRUE(plain.Evaluate(params.data(), r1.data(), j1.data()));
  ASSERT_TRUE(shifted.Evaluate(params.data(), r2.data(), j2.data()));
  for (int i = 0; i < m; ++i) EXPECT_NEAR(r2[i], r1[i] - 2.0 * offset[i], 1e-15);
  EXPECT_EQ(J1, J2);
  shifted.set_weight(9.0);
  ASSERT_TRUE(shifted.Evaluate(params.data(), r2.data(), nullptr));
  for (int i = 0; i < m; ++i) EXPECT_NEAR(r2[i], 1.5 * r1[i] - 3.0 * offset[i], 1e-14);
}

}  // namespace
}  // namespace sdog
