// The SQP solver's phases on a small DOG (sqp_solver.h): an ordinary iteration lowers the
// objective and restores the constraints to the per-iteration tolerance, the last iteration's
// polish reaches the final tolerance, restoration alone moves a state onto the constraints, a
// stationary state takes no step, and a failure rolls back.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/problem/dog_problem.h"
#include "solver/problem/scenario.h"
#include "solver/sqp/sqp_solver.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

struct SmallProblem {
  DogModel model = build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {13, 9});
  DogProblem problem{model.fine, model.fine_topology};
  Scenario scenario = corners_scenario(model.fine, 4, 0);
  SqpOptions options;
  SmallProblem() {
    problem.weights.fold_bias = 0;  // no folding mode here: the solver alone
    scenario.install(problem);
  }
  SqpSolver solver() {
    std::vector<WeightedTerm> terms = problem.objective_terms();
    terms[kFoldBias].weight = 0;
    return SqpSolver(model.fine.vertex_count(), terms, problem.dog, options);
  }
  double dog_max(SqpSolver& s, const Dofs& x) {
    return s.constraint_values(x).lpNorm<Eigen::Infinity>();
  }
};

TEST(SqpSolver, AnIterationLowersTheObjectiveAndRestoresTheConstraints) {
  SmallProblem p;
  SqpSolver s = p.solver();
  Dofs x = p.problem.rest();
  p.scenario.apply(p.problem, 0.25);  // the corner moved a quarter of the way
  const double before = s.objective(x);
  const SqpReport r = s.iterate(x);
  ASSERT_FALSE(r.failed) << r.failure;
  EXPECT_EQ(r.work.steps, 1);  // max_steps 1
  EXPECT_GE(r.work.factorizations, 1);
  EXPECT_GT(r.step_length, 0);
  EXPECT_LT(s.objective(x), before);
  EXPECT_LE(r.constraint_max, p.options.constraint_tolerance);
  EXPECT_DOUBLE_EQ(r.constraint_max, p.dog_max(s, x));
}

TEST(SqpSolver, MoreStepsPerIterationConvergeFurther) {
  SmallProblem one, five;
  five.options.max_steps = 5;
  SqpSolver a = one.solver(), b = five.solver();
  Dofs xa = one.problem.rest(), xb = five.problem.rest();
  one.scenario.apply(one.problem, 0.25);
  five.scenario.apply(five.problem, 0.25);
  ASSERT_FALSE(a.iterate(xa).failed);
  const SqpReport r = b.iterate(xb);
  ASSERT_FALSE(r.failed) << r.failure;
  EXPECT_GT(r.work.steps, 1);
  EXPECT_LE(r.work.steps, 5);
  EXPECT_LT(b.objective(xb), a.objective(xa));
}

TEST(SqpSolver, TheLastIterationPolishesToTheFinalTolerance) {
  SmallProblem p;
  SqpSolver s = p.solver();
  Dofs x = p.problem.rest();
  for (int k = 1; k <= 4; ++k) {
    p.scenario.apply(p.problem, 0.25 * k);
    ASSERT_FALSE(s.iterate(x, k == 4).failed) << "iteration " << k;
  }
  EXPECT_LE(p.dog_max(s, x), p.options.final_constraint_tolerance);
}

TEST(SqpSolver, RestorationAloneMovesAStateOntoTheConstraints) {
  SmallProblem p;
  SqpSolver s = p.solver();
  Dofs x = p.problem.rest();
  for (Eigen::Index i = 2; i < x.size(); i += 3)
    x[i] += 0.05 * std::sin(0.7 * static_cast<double>(i));
  const double before = p.dog_max(s, x);
  ASSERT_GT(before, 10 * p.options.constraint_tolerance);
  const double objective = s.objective(x);
  const SqpReport r = s.restore_constraints(x);
  ASSERT_FALSE(r.failed) << r.failure;
  EXPECT_EQ(r.work.steps, 0);  // no optimality step
  EXPECT_GT(r.work.restoration_steps, 0);
  EXPECT_LE(p.dog_max(s, x), p.options.constraint_tolerance);
  EXPECT_LT(s.objective(x), 2 * objective + 1);  // a small move, not a new shape
  // The projection goes on to the final tolerance.
  const SqpReport projected = s.project(x);
  ASSERT_FALSE(projected.failed) << projected.failure;
  EXPECT_LE(p.dog_max(s, x), p.options.final_constraint_tolerance);
}

TEST(SqpSolver, AStationaryStateTakesNoStep) {
  SmallProblem p;
  SqpSolver s = p.solver();
  Dofs x = p.problem.rest();  // no target moved: the flat sheet is optimal
  const SqpReport r = s.iterate(x);
  ASSERT_FALSE(r.failed) << r.failure;
  EXPECT_EQ(r.work.steps, 0);
  EXPECT_EQ(x, p.problem.rest());
}

TEST(SqpSolver, ANonFiniteStateFailsAndRollsBack) {
  SmallProblem p;
  SqpSolver s = p.solver();
  p.scenario.apply(p.problem, 0.25);
  Dofs x = p.problem.rest();
  x[4] = std::numeric_limits<double>::quiet_NaN();
  const Dofs x0 = x;
  const Eigen::VectorXd lambda0 = s.multipliers();
  const SqpReport r = s.iterate(x);
  EXPECT_TRUE(r.failed);
  EXPECT_NE(r.failure.find("not finite"), std::string::npos) << r.failure;
  EXPECT_TRUE(x.hasNaN() && (x.array() == x0.array() || x.array().isNaN()).all());
  EXPECT_EQ(s.multipliers(), lambda0);
}

TEST(SqpSolver, ChecksItsOptionsAgainstTheirTable) {
  SqpOptions o;
  EXPECT_EQ(o.validate(), "");
  o.max_steps = 0;
  EXPECT_EQ(o.validate(), "max_steps must be at least 1");
  o = SqpOptions();
  o.armijo = 0.5;
  EXPECT_EQ(o.validate(), "armijo must be in (0, 0.5)");
  o = SqpOptions();
  o.polish_epsilon = 1e-14;  // rho_max below 1/polish_epsilon
  EXPECT_NE(o.validate().find("rho_max must be at least"), std::string::npos);
}

}  // namespace
}  // namespace sdog
