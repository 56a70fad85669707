// Local restoration (local_restoration.h): the neighbourhood of the violated rows, and a step that
// moves only its vertices and lowers those rows' residual.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/problem/dog_problem.h"
#include "solver/sqp/local_restoration.h"
#include "solver/sqp/sqp_solver.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

TEST(LocalRestoration, MovesOnlyTheNeighbourhoodOfTheViolatedRows) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {21, 15});
  const DogProblem problem(model.fine, model.fine_topology);
  const int n = model.fine.vertex_count();
  SqpSolver solver(n, problem.objective_terms(), problem.dog, SqpOptions());
  // One vertex moved in the plane of the flat sheet: only the rows of the blocks around it are
  // violated.
  Dofs x = problem.rest();
  const int lifted = n / 2;
  x[3 * lifted] += 0.1;
  Eigen::SparseMatrix<double> K;
  const SqpSolver::Linearization lin = solver.linearization(x, 0, &K);
  const double tolerance = 1e-8;
  const LocalRestoration local(n, problem.dog, 1);
  const std::vector<int> near = local.neighbourhood(lin.c, tolerance);
  ASSERT_FALSE(near.empty());
  EXPECT_TRUE(std::binary_search(near.begin(), near.end(), lifted));
  EXPECT_LT(static_cast<int>(near.size()), n / 4);
  // More rings reach further.
  EXPECT_GT(LocalRestoration(n, problem.dog, 2).neighbourhood(lin.c, tolerance).size(),
            near.size());
  EXPECT_TRUE(local.neighbourhood(Eigen::VectorXd::Zero(lin.c.size()), tolerance).empty());

  Eigen::VectorXd d;
  ASSERT_TRUE(local.step(near, lin.c, lin.J, K, 1e6, 1e-8, d));
  for (int v = 0; v < n; ++v)
    if (!std::binary_search(near.begin(), near.end(), v)) {
      EXPECT_EQ(d.segment<3>(3 * v).norm(), 0)
          << "vertex " << v << " outside the neighbourhood moved";
    }
  const Eigen::VectorXd after = solver.constraint_values(x + d);
  EXPECT_LT(after.squaredNorm(), 0.5 * lin.c.squaredNorm());
  EXPECT_FALSE(local.step({}, lin.c, lin.J, K, 1e6, 1e-8, d));
}

}  // namespace
}  // namespace sdog
