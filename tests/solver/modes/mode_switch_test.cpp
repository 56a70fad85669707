// Switching modes in the middle of a run (switch_mode, the switches of a RunSetup): every mode
// takes over the state another one left without a jump and keeps the DOG constraints; the coarse
// modes derive their coarse mesh from the state they take over.
#include <gtest/gtest.h>

#include <map>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/modes/mode_factory.h"
#include "tests/solver/run_recorder.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

const DogModel& model() {
  static const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {21, 21});
  return m;
}

struct SwitchedRun {
  test::RunResult result;
  std::vector<double> step;  ///< per iteration: largest vertex displacement
};

SwitchedRun run_with_switches(const RunConfig& config, ModeKind first) {
  RunSetup setup(model(), first, config);
  SwitchedRun out;
  Dofs previous = setup.positions();
  struct StepRecorder : test::Recorder {
    Dofs* previous;
    std::vector<double>* step;
    void on_iteration(const IterationReport& r, const Dofs& x) override {
      test::Recorder::on_iteration(r, x);
      step->push_back(
          (x - *previous).lpNorm<Eigen::Infinity>());  // coordinates: a bound on vertex moves
      *previous = x;
    }
  } recorder;
  recorder.previous = &previous;
  recorder.step = &out.step;
  out.result.summary = setup.run({&recorder});
  out.result.reports = recorder.reports;
  out.result.x = setup.positions();
  return out;
}

// Every mode takes over from another and hands over to the next; the standard mode finishes.
TEST(ModeSwitch, EveryModeTakesOverWithoutAJump) {
  RunConfig config = test::short_run(100, 30);
  // The step sizes are compared with the standard mode's one step per iteration of the drag.
  config.standard.converge = false;
  config.switches = {{16, ModeKind::kTwoLevel},   {31, ModeKind::kCoarse},
                     {46, ModeKind::kSubsolvers}, {61, ModeKind::kVsAdmm},
                     {71, ModeKind::kJAdmm},      {76, ModeKind::kProxJAdmm},
                     {81, ModeKind::kStandard}};
  const SwitchedRun s = run_with_switches(config, ModeKind::kStandard);
  ASSERT_FALSE(s.result.summary.failed()) << s.result.summary.failure;
  ASSERT_EQ(s.result.reports.size(), 130u);

  std::map<int, std::string> expected_mode;
  std::string current = "standard";
  size_t next = 0;
  for (int k = 1; k <= 130; ++k) {
    if (next < config.switches.size() && config.switches[next].iteration == k)
      current = enum_name(config.switches[next++].mode);
    expected_mode[k] = current;
  }
  for (const auto& r : s.result.reports) {
    EXPECT_EQ(r.mode, expected_mode[r.iteration]) << "iteration " << r.iteration;
    EXPECT_LT(r.diagnostics.dog_max, 1e-4) << "iteration " << r.iteration << " (" << r.mode << ")";
  }
  // No jump where a mode takes over: the switch iteration moves the sheet no more than the
  // iterations of the target drag do (about 0.1 mesh units each here).
  double typical = 0;
  for (int k = 2; k <= 15; ++k) typical = std::max(typical, s.step[k - 1]);
  for (const ModeSwitch& sw : config.switches)
    EXPECT_LT(s.step[sw.iteration - 1], 4 * typical)
        << "iteration " << sw.iteration << " (" << enum_name(sw.mode)
        << " takes over): " << s.step[sw.iteration - 1] << " against " << typical;

  // The standard mode's last iteration polishes the constraints as in a run of its own. (It does
  // not refold creases the patch modes left unfolded: see
  // StandardKeepsTheConstraintsWhenItCannotRefold.)
  EXPECT_LT(s.result.reports.back().diagnostics.dog_max, 1e-6);
  EXPECT_TRUE(std::isfinite(s.result.reports.back().diagnostics.terms[kBending]));
}

// The standard mode taking over a sheet another mode left with creases folded the wrong way:
// converging iterations refold it and keep the DOG constraints. While it stays unfolded, an
// iteration climbs the fold-bias ladder (up to 1e6) once, not once per sub-step.
TEST(ModeSwitch, StandardRefoldsASheetHandedOverUnfolded) {
  RunConfig config = test::short_run(30, 5);
  config.switches = {{10, ModeKind::kStandard}};
  config.twolevel.standard_finish = 0;
  const SwitchedRun s = run_with_switches(config, ModeKind::kTwoLevel);
  ASSERT_FALSE(s.result.summary.failed()) << s.result.summary.failure;
  const auto& reports = s.result.reports;
  ASSERT_EQ(reports.size(), 35u);
  ASSERT_FALSE(reports[8].step.folded)
      << "the case this test is about: a sheet handed over unfolded";
  EXPECT_GT(reports[9].step.work.fold_retries, 0);
  int folded = 0;
  for (size_t k = 9; k < reports.size(); ++k) {
    folded += reports[k].step.folded;
    // No ladder climbed again and again: an iteration whose escalation (from the base weight 1 to
    // max_fold_bias 1e6, six rungs) ended unfolded takes none in its later sub-steps; one that
    // folded the sheet may be followed by one more. The cost stays that of a few sub-steps.
    EXPECT_LE(reports[k].step.work.fold_retries, 12) << "iteration " << reports[k].iteration;
    EXPECT_LE(reports[k].step.work.factorizations, 60) << "iteration " << reports[k].iteration;
    EXPECT_LT(reports[k].diagnostics.dog_max, 1e-4) << "iteration " << reports[k].iteration;
  }
  // A crease site near flat may flip for an iteration on the way (which ones depends on rounding).
  EXPECT_GE(folded, static_cast<int>(reports.size() - 9) - 3);
  EXPECT_TRUE(reports.back().step.folded);
}

// With the thesis's iteration the fold-bias escalation cannot refold that sheet, and the iteration
// then keeps its least unfolded attempt at the base weight instead of the last one at 1e14 (which
// broke the DOG constraints and left a weighted objective of 1e14 behind; the reference's
// behaviour).
TEST(ModeSwitch, StandardKeepsTheConstraintsWhenItCannotRefold) {
  RunConfig config = test::short_run(30, 5);
  config.standard.converge = false;
  config.standard.max_fold_bias = 1e14;
  config.switches = {{10, ModeKind::kStandard}};
  config.twolevel.standard_finish =
      0;  // two-level iterations up to the switch (a finish would start at 6)
  const SwitchedRun s = run_with_switches(config, ModeKind::kTwoLevel);
  ASSERT_FALSE(s.result.summary.failed()) << s.result.summary.failure;
  const auto& reports = s.result.reports;
  ASSERT_EQ(reports.size(), 35u);
  const auto& before = reports[8];  // iteration 9, the two-level mode's last
  ASSERT_FALSE(before.step.folded) << "the case this test is about: a sheet handed over unfolded";
  int exhausted = 0;
  for (size_t k = 9; k < reports.size(); ++k) {
    const auto& r = reports[k];
    ASSERT_EQ(r.mode, "standard");
    EXPECT_LT(r.diagnostics.dog_max, 1e-4) << "iteration " << r.iteration;
    if (r.step.folded || r.step.work.fold_retries == 0) continue;
    ++exhausted;
    // The objective is at the base fold-bias weight again: of the order of the handed-over sheet's.
    EXPECT_LT(r.diagnostics.objective, 10 * before.diagnostics.objective)
        << "iteration " << r.iteration;
  }
  EXPECT_GT(exhausted, 0) << "no iteration exhausted the escalation: the test no longer covers it";
}

// The coarse modes derive the coarse mesh from the state they take over: a switch into twolevel at
// a deformed state continues smoothly, and a coarse run can start from a given state (flatten).
TEST(ModeSwitch, CoarseModesStartFromTheStateTheyTakeOver) {
  RunConfig config = test::short_run(60, 10);
  config.standard.converge = false;  // as above
  config.switches = {{41, ModeKind::kTwoLevel}};
  const SwitchedRun s = run_with_switches(config, ModeKind::kStandard);
  ASSERT_FALSE(s.result.summary.failed()) << s.result.summary.failure;
  // Iteration 41 moves no more than the standard iterations before it; a coarse mesh left flat
  // would drag the sheet back by its whole deformation.
  double before = 0;
  for (int k = 30; k <= 40; ++k) before = std::max(before, s.step[k - 1]);
  EXPECT_LT(s.step[40], 3 * before) << s.step[40] << " against " << before;
  for (const auto& r : s.result.reports)
    EXPECT_LT(r.diagnostics.dog_max, 1e-4) << "iteration " << r.iteration;

  RunConfig flatten = test::short_run(8, 2);
  flatten.scenario = ScenarioKind::kFlatten;
  flatten.fold_angle = 30;
  const test::RunResult r = test::run_mode("coarse", model(), flatten);
  ASSERT_FALSE(r.summary.failed()) << r.summary.failure;
  for (const auto& rep : r.reports)
    EXPECT_LT(rep.diagnostics.dog_max, 1e-4) << "iteration " << rep.iteration;
}

}  // namespace
}  // namespace sdog
