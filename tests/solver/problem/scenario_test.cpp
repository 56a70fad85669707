// Scenarios (problem/scenario.h): what the thesis protocol and the fold scenario ask for, targets
// moving linearly in time and then held, installation into a problem, and the fold seed of a
// start state.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/problem/dog_problem.h"
#include "solver/problem/fold_seed.h"
#include "solver/problem/scenario.h"
#include "solver/terms/crease_geometry.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

const DogModel& model() {
  static const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {21, 15});
  return m;
}

TEST(Scenario, TheCornersProtocolHoldsOneCornerAndDragsTheOther) {
  const DogMesh& mesh = model().fine;
  const Scenario s = corners_scenario(mesh, 250, 50);
  ASSERT_EQ(s.positions.size(), 2u);
  const PositionConstraint& a = s.positions[0];
  const PositionConstraint& c = s.positions[1];
  EXPECT_EQ(mesh.grid[a.vertex], Eigen::Vector2i(0, 0));
  EXPECT_EQ(mesh.grid[c.vertex], Eigen::Vector2i(mesh.nx() - 1, mesh.ny() - 1));
  EXPECT_EQ(a.start, a.end);
  // The thesis's end point: (0.6 x_c, 0.5 (y_c + y_a), 0.4 (y_c + y_a)).
  const double xc = mesh.V(c.vertex, 0), yc = mesh.V(c.vertex, 1), ya = mesh.V(a.vertex, 1);
  EXPECT_EQ(c.end, Eigen::Vector3d(0.6 * xc, 0.5 * (yc + ya), 0.4 * (yc + ya)));
  EXPECT_TRUE(s.angles.empty());
  EXPECT_TRUE(s.keeps_folds);
}

TEST(Scenario, TargetsMoveLinearlyThenHold) {
  const Scenario s = corners_scenario(model().fine, 4, 2);
  EXPECT_EQ(s.time_of(1), 0.25);
  EXPECT_EQ(s.time_of(2), 0.5);
  EXPECT_EQ(s.time_of(4), 1.0);
  EXPECT_EQ(s.time_of(6), 1.0);
  Scenario none = s;
  none.iterations = 0;
  EXPECT_EQ(none.time_of(1), 1.0);
  DogProblem problem(model().fine, model().fine_topology);
  s.install(problem);
  ASSERT_EQ(problem.positions.block_count(), 2);
  EXPECT_EQ(problem.positions.target(1), s.positions[1].start);  // installed at t = 0
  s.apply(problem, 0.5);
  EXPECT_TRUE(
      problem.positions.target(1).isApprox(0.5 * (s.positions[1].start + s.positions[1].end)));
}

TEST(Scenario, TheFoldScenarioAsksForTheAngleAtEveryFoldSite) {
  const DogMesh& mesh = model().fine;
  const Scenario s = fold_scenario(mesh, 60, 40, 10);
  const auto sites = fold_sites(mesh);
  ASSERT_FALSE(sites.empty());
  ASSERT_EQ(s.angles.size(), sites.size());
  for (size_t k = 0; k < sites.size(); ++k) {
    EXPECT_EQ(s.angles[k].point, sites[k].point);
    EXPECT_EQ(s.angles[k].start_degrees, 0);
    EXPECT_EQ(s.angles[k].end_degrees, 60);
  }
  ASSERT_EQ(s.curve_signs.size(), mesh.stitching.curves.size());
  for (double sign : s.curve_signs) EXPECT_EQ(sign, 1.0);
  for (double sign : fold_scenario(mesh, -30).curve_signs) EXPECT_EQ(sign, -1.0);
  // A fold amount of 25% ends every site at a quarter of its angle.
  const Scenario quarter = fold_scenario(mesh, 60, 40, 10, 25);
  ASSERT_EQ(quarter.angles.size(), sites.size());
  for (const auto& a : quarter.angles) EXPECT_DOUBLE_EQ(a.end_degrees, 15);
  // Flat targets at t = 0, the end's at t = 1; every site's alpha in [0, 90] degrees.
  DogProblem problem(mesh, model().fine_topology);
  s.install(problem);
  ASSERT_EQ(problem.angles.block_count(), static_cast<int>(sites.size()));
  for (int b = 0; b < problem.angles.block_count(); ++b) {
    EXPECT_EQ(problem.angles.target(b), 0);
    EXPECT_GE(problem.angles.alpha(b), 0);
    EXPECT_LE(problem.angles.alpha(b), M_PI / 2);
  }
  s.apply(problem, 1);
  for (int b = 0; b < problem.angles.block_count(); ++b)
    EXPECT_DOUBLE_EQ(problem.angles.target(b), M_PI / 3);
  // A start state tilted towards the fold (the flat sheet is a symmetric point).
  EXPECT_GT((s.start(mesh) - problem.rest()).lpNorm<Eigen::Infinity>(), 0);
}

}  // namespace
}  // namespace sdog
