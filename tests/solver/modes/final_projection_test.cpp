// The last iteration of the patch modes (final_projection.h): an ordinary patch round, then the
// whole sheet projected onto the DOG constraints to the final tolerance.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/modes/final_projection.h"
#include "solver/problem/diagnostics.h"
#include "solver/terms/crease_geometry.h"
#include "tests/solver/run_recorder.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

const DogModel& model() {
  static const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {21, 21});
  return m;
}

// A standard run's state, every coordinate nudged by up to `amplitude`.
Dofs nudged_run_state(double amplitude) {
  const test::RunResult r = test::run_mode("standard", model(), test::short_run(30, 0));
  EXPECT_FALSE(r.summary.failed()) << r.summary.failure;
  Dofs x = r.x;
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += amplitude * std::sin(1.7 * i);
  return x;
}

// A state off the DOG constraints by about 1e-4 (a standard run's state, nudged), projected: on
// the constraints to the final tolerance, moved by little more than it was nudged.
TEST(FinalProjection, MovesTheSheetOntoTheConstraintsByLittle) {
  DogProblem problem(model().fine, model().fine_topology, RunConfig().weights);
  Dofs x = nudged_run_state(3e-5);
  const double before = diagnose(problem, x).dog_max;
  ASSERT_GT(before, 1e-5);
  const Dofs nudged = x;
  const SqpOptions sqp;
  FinalProjection projection(problem, sqp);
  StepReport report;
  ASSERT_TRUE(projection.project(x, report)) << report.failure;
  EXPECT_LT(diagnose(problem, x).dog_max, sqp.final_constraint_tolerance);
  EXPECT_GT(report.work.restoration_steps, 0);
  // Near flat regions the constraints are nearly quadratic in the normal motion, so removing a
  // residual r takes a move of about sqrt(r); the objective barely changes.
  EXPECT_LT((x - nudged).lpNorm<Eigen::Infinity>(), std::sqrt(before));
  EXPECT_NEAR(diagnose(problem, x).objective, diagnose(problem, nudged).objective,
              1e-3 * diagnose(problem, nudged).objective);
  // A state already on the constraints is left alone.
  const Dofs projected = x;
  StepReport again;
  ASSERT_TRUE(projection.project(x, again));
  EXPECT_EQ(again.work.restoration_steps, 0);
  EXPECT_TRUE(x == projected);
}

// projection_steps bounds the projection: with 1, one global step and then one that may be local,
// which leave a state nudged further off short of the final tolerance that the default reaches
// in more steps.
TEST(FinalProjection, TakesAtMostProjectionStepsPerPhase) {
  DogProblem problem(model().fine, model().fine_topology, RunConfig().weights);
  const Dofs nudged = nudged_run_state(2e-3);
  const double before = diagnose(problem, nudged).dog_max;
  auto project = [&](const SqpOptions& sqp, StepReport& report) {
    Dofs x = nudged;
    FinalProjection projection(problem, sqp);
    EXPECT_TRUE(projection.project(x, report)) << report.failure;
    return diagnose(problem, x).dog_max;
  };
  StepReport full, short_one;
  ASSERT_LE(project(SqpOptions(), full), SqpOptions().final_constraint_tolerance);
  ASSERT_GT(full.work.restoration_steps, 2);
  SqpOptions one_step;
  one_step.projection_steps = 1;
  const double after = project(one_step, short_one);
  EXPECT_GE(short_one.work.restoration_steps, 1);
  EXPECT_LE(short_one.work.restoration_steps, 2);
  EXPECT_LT(after, before);
  EXPECT_GT(after, SqpOptions().final_constraint_tolerance);
}

// polish_factorizations bounds the projection on its own too (the patch modes' last iteration):
// with a budget of 1 it stops at its first factorisation, short of the final tolerance that the
// unbudgeted projection reaches with more steps.
TEST(FinalProjection, MakesAtMostPolishFactorizations) {
  DogProblem problem(model().fine, model().fine_topology, RunConfig().weights);
  auto project = [&](int budget, StepReport& report) {
    Dofs x = nudged_run_state(2e-3);
    SqpOptions sqp;
    sqp.polish_factorizations = budget;
    FinalProjection projection(problem, sqp);
    EXPECT_TRUE(projection.project(x, report)) << report.failure;
    return diagnose(problem, x).dog_max;
  };
  StepReport unlimited, budgeted;
  ASSERT_LE(project(0, unlimited), SqpOptions().final_constraint_tolerance);
  ASSERT_GT(unlimited.work.restoration_steps, 1);
  EXPECT_GT(project(1, budgeted), SqpOptions().final_constraint_tolerance);
  EXPECT_EQ(budgeted.work.factorizations, 1);
  EXPECT_LT(budgeted.work.restoration_steps, unlimited.work.restoration_steps);
}

struct Finish {
  Diagnostics diagnostics;
  int unfolded = 0;
};

// The state after iteration `k` of a run of `iterations` + `hold` iterations.
Finish after(const char* name, RunConfig config, int k) {
  RunSetup setup(model(), parse_enum<ModeKind>(name), config);
  struct Keep : RunObserver {
    int k;
    Dofs x;
    Diagnostics d;
    void on_iteration(const IterationReport& r, const Dofs& state) override {
      if (r.iteration == k) x = state, d = r.diagnostics;
    }
  } keep;
  keep.k = k;
  const RunSummary summary = setup.run({&keep});
  EXPECT_FALSE(summary.failed()) << name << ": " << summary.failure;
  return {keep.d, check_folded(model().fine, setup.problem().sites, keep.x).violations};
}

// The last iteration of a run in the patch modes is an ordinary iteration and the projection: the
// same objective and folds as the same iteration in a longer run, and DOG below the final
// tolerance.
TEST(FinalProjection, TheLastIterationOfThePatchModesKeepsTheResult) {
  RunConfig config = test::short_run(60, 20);
  config.twolevel.standard_finish = 0;  // twolevel's own last iteration, not its standard finish
  RunConfig longer = config;
  longer.hold += 1;
  for (const char* name : {"subsolvers", "twolevel", "coarse"}) {
    const Finish last = after(name, config, 80);
    const Finish ordinary = after(name, longer, 80);
    EXPECT_LT(last.diagnostics.dog_max, config.standard.sqp.final_constraint_tolerance) << name;
    EXPECT_GT(ordinary.diagnostics.dog_max, config.standard.sqp.final_constraint_tolerance) << name;
    EXPECT_NEAR(last.diagnostics.objective, ordinary.diagnostics.objective,
                1e-2 * ordinary.diagnostics.objective)
        << name;
    EXPECT_EQ(last.unfolded, ordinary.unfolded) << name;
  }
}

}  // namespace
}  // namespace sdog
