// The standard SQP solver on whole runs: the constraint bars of a run after every iteration, the
// fold direction, failure handling and determinism. (The eight thesis runs: tests/slow/.)
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/modes/mode_factory.h"
#include "solver/modes/standard_mode.h"
#include "solver/problem/crease_angles.h"
#include "solver/problem/diagnostics.h"
#include "solver/run/run.h"
#include "solver/run/run_config.h"
#include "solver/sqp/sqp_solver.h"
#include "tests/solver/run_recorder.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

using test::Recorder;
using test::RunResult;

RunResult run(const DogModel& model, const RunConfig& config) {
  return test::run_mode("standard", model, config);
}

// The bars of a run: DOG constraints below 1e-4 after every iteration and 1e-6 at the end,
// folded at the end.
void expect_constraint_bars(const RunResult& r, int iterations) {
  ASSERT_FALSE(r.summary.failed()) << r.summary.failure;
  ASSERT_EQ(r.summary.iterations, iterations);
  ASSERT_EQ(static_cast<int>(r.reports.size()), iterations);
  for (const auto& rep : r.reports) {
    EXPECT_LT(rep.diagnostics.dog_max, 1e-4) << "iteration " << rep.iteration;
    // While the targets move every iteration takes a step (a held, converged state may not).
    if (rep.t < 1) {
      EXPECT_GE(rep.step.work.steps, 1) << "iteration " << rep.iteration;
    }
  }
  EXPECT_LT(r.reports.back().diagnostics.dog_max, 1e-6);
  EXPECT_TRUE(r.reports.back().step.folded);
}

TEST(StandardMode, CornersProtocolOnAProjectPattern) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {21, 15});
  RunConfig config = test::thesis_config();
  config.iterations = 80;
  config.hold = 20;
  const RunResult r = run(model, config);
  expect_constraint_bars(r, 100);
  // The sheet is really deformed: the dragged corner reached its target up to the soft weight.
  const auto& last = r.reports.back();
  EXPECT_GT(last.diagnostics.terms[kBending], 1e-2);
  EXPECT_LT(last.diagnostics.terms[kPositions], 1e-2);
  EXPECT_LT(last.diagnostics.edge_strain_max, 0.05);
  EXPECT_LT(last.diagnostics.stitch_gap_max, 0.1);
  // After the targets stop moving the objective settles: the held phase changes it little.
  const double at_hold = r.reports[79].diagnostics.objective;
  EXPECT_NEAR(last.diagnostics.objective, at_hold, 0.05 * at_hold);
}

// When the polish of the last iteration stops short of the final tolerance, SqpSolver::project
// finishes it. Here the polish is starved (no exact-Hessian
// steps, two restoration steps) so that it must stop short on a small case.
TEST(StandardMode, AShortPolishIsFinishedByTheProjection) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {21, 21});
  RunConfig config =
      test::thesis_run(25, 5);  // the last iterations are held: comparable objectives
  config.standard.sqp.polish_steps = 0;
  config.standard.sqp.max_restoration_steps = 1;
  const RunResult r = run(model, config);
  ASSERT_FALSE(r.summary.failed()) << r.summary.failure;
  const double final_tolerance = config.standard.sqp.final_constraint_tolerance;
  // The iteration before the last one is far from the final tolerance (one restoration step).
  ASSERT_GT(r.reports[28].diagnostics.dog_max, 10 * final_tolerance);
  const auto& last = r.reports.back();
  EXPECT_LT(last.diagnostics.dog_max, final_tolerance);
  EXPECT_GT(last.step.work.restoration_steps, 2);  // more than the polish's own two
  EXPECT_TRUE(last.step.folded);
  EXPECT_NEAR(last.diagnostics.objective, r.reports[28].diagnostics.objective,
              0.02 * r.reports[28].diagnostics.objective);
}

TEST(StandardMode, FoldScenarioReachesTheDihedralAngle) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {21, 15});
  RunConfig config = test::thesis_config();
  config.scenario = ScenarioKind::kFold;
  config.fold_angle = 60;
  config.iterations = 40;
  config.hold = 10;
  const RunResult r = run(model, config);
  expect_constraint_bars(r, 50);
  const auto& last = r.reports.back().diagnostics;
  // Angle residuals are cosines; a 60 degree fold has them far from zero when it is not reached.
  EXPECT_LT(last.terms[kAngles], 1e-3);
  // It is a real fold, not a shear in the plane: the sheet leaves the plane by a good fraction of
  // its size (21 grid lines).
  double zmin = 0, zmax = 0;
  for (Eigen::Index v = 0; v < r.x.size() / 3; ++v) {
    zmin = std::min(zmin, r.x[3 * v + 2]);
    zmax = std::max(zmax, r.x[3 * v + 2]);
  }
  EXPECT_GT(zmax - zmin, 2.0);
}

TEST(StandardMode, MountainIsTheMirrorImageOfValley) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {21, 15});
  RunConfig config;
  config.scenario = ScenarioKind::kFold;
  config.iterations = 15;
  config.hold = 0;
  config.fold_angle = 45;
  const RunResult valley = run(model, config);
  config.fold_angle = -45;
  const RunResult mountain = run(model, config);
  ASSERT_FALSE(valley.summary.failed());
  ASSERT_FALSE(mountain.summary.failed());
  double worst = 0, height = 0;
  for (Eigen::Index v = 0; v < valley.x.size() / 3; ++v) {
    worst = std::max({worst, std::abs(valley.x[3 * v] - mountain.x[3 * v]),
                      std::abs(valley.x[3 * v + 1] - mountain.x[3 * v + 1]),
                      std::abs(valley.x[3 * v + 2] + mountain.x[3 * v + 2])});
    height = std::max(height, std::abs(valley.x[3 * v + 2]));
  }
  EXPECT_GT(height, 0.5);
  EXPECT_LT(worst, 1e-8);
}

TEST(StandardMode, NonFiniteTargetsFailAndRollBack) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {21, 15});
  RunConfig config;
  Scenario scenario = make_scenario(config, model.fine);
  ASSERT_FALSE(scenario.positions.empty());
  scenario.positions.back().end = Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  RunSetup setup(model, ModeKind::kStandard, config, scenario);
  const Dofs x0 = setup.positions();
  Recorder recorder;
  const RunSummary s = setup.run({&recorder});
  const Dofs& x = setup.positions();
  EXPECT_TRUE(s.failed());
  EXPECT_EQ(s.iterations, 0);
  EXPECT_NE(s.failure.find("iteration 1"), std::string::npos) << s.failure;
  EXPECT_NE(s.failure.find("not finite"), std::string::npos) << s.failure;
  ASSERT_EQ(recorder.reports.size(), 1u);
  EXPECT_TRUE(recorder.reports[0].step.failed);
  EXPECT_TRUE(x == x0) << "the failed iteration was not rolled back";
}

// A factorisation that fails in a held iteration (here forced: three whole refactorisations, every
// rho and shift, fail in a row) is taken back and retried with a shorter step: the run goes on,
// ends converged and folded the drawn way, and counts the recovered passes.
TEST(StandardMode, AFailedFactorizationIsRecovered) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {21, 15});
  RunConfig config;
  config.scenario = ScenarioKind::kFold;
  config.fold_angle = 60;
  config.iterations = 5;
  config.hold = 10;
  RunSetup setup(model, ModeKind::kStandard, config);
  auto& mode = dynamic_cast<StandardMode&>(setup.mode());
  struct Injector : RunObserver {
    StandardMode* mode;
    void on_iteration(const IterationReport& r, const Dofs&) override {
      if (r.iteration == 5) mode->sqp().inject_factorization_failures(3 * 24);
    }
  } injector;
  injector.mode = &mode;
  Recorder recorder;
  const RunSummary s = setup.run({&injector, &recorder});
  ASSERT_FALSE(s.failed()) << s.failure;
  ASSERT_EQ(s.iterations, 15);
  int recovered = 0;
  for (const IterationReport& r : recorder.reports) recovered += r.step.work.recovered_failures;
  EXPECT_GE(recovered, 1) << "no pass failed: the injection did not reach the solver";
  const IterationReport& last = recorder.reports.back();
  EXPECT_TRUE(last.step.converged.value_or(false));
  EXPECT_TRUE(last.step.folded);
  EXPECT_LT(last.diagnostics.dog_max, 1e-6);
  EXPECT_EQ(last.diagnostics.angles_met.against(), 0);
  EXPECT_GT(last.diagnostics.angles_met.bent_sites, 0);
}

TEST(StandardMode, RepeatedRunsAreIdentical) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {15, 15});
  RunConfig config;
  config.iterations = 20;
  config.hold = 5;
  const RunResult a = run(model, config);
  const RunResult b = run(model, config);
  ASSERT_FALSE(a.summary.failed());
  EXPECT_TRUE(a.x == b.x);
  for (size_t k = 0; k < a.reports.size(); ++k)
    EXPECT_EQ(a.reports[k].diagnostics.objective, b.reports[k].diagnostics.objective) << k;
}

}  // namespace
}  // namespace sdog
