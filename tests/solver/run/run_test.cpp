// The run driver (run/run.h): the iteration context each iteration gets, the diagnostics measured
// on the fine problem, mode switches, and why a run ends.
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "base/errors.h"
#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/problem/diagnostics.h"
#include "solver/run/run.h"
#include "solver/run/run_setup.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

const DogModel& model() {
  static const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {13, 9});
  return m;
}

// A mode that records what it is told, sets the targets of its time (as every mode does) and moves
// one coordinate a little; fails or throws a vertex far off its neighbours (diverges) when asked
// to.
class ProbeMode : public Mode {
 public:
  ProbeMode(DogProblem& problem, const Scenario& scenario)
      : problem_(problem), scenario_(scenario) {}
  ModeKind kind() const override { return ModeKind::kStandard; }
  StepReport iterate(const IterationContext& ctx, Dofs& x) override {
    contexts.push_back(ctx);
    scenario_.apply(problem_, ctx.t);
    StepReport r;
    if (static_cast<int>(contexts.size()) == fail_at) {
      r.failed = true;
      r.failure = "asked to fail";
      return r;
    }
    x[2] += 0.01;
    if (static_cast<int>(contexts.size()) == diverge_at)
      x[x.size() / 2 / 3 * 3] += 0.5;  // a middle vertex
    r.work.steps = 1;
    if (cancel_after > 0 && static_cast<int>(contexts.size()) == cancel_after) cancel->store(true);
    return r;
  }
  std::vector<IterationContext> contexts;
  int fail_at = -1, diverge_at = -1, cancel_after = -1;
  std::atomic<bool>* cancel = nullptr;

 private:
  DogProblem& problem_;
  const Scenario& scenario_;
};

struct RunCase {
  DogProblem problem{model().fine, model().fine_topology};
  Scenario scenario = corners_scenario(model().fine, 4, 2);
  Dofs x = problem.rest();
  RunCase() { scenario.install(problem); }
};

TEST(Run, EveryIterationGetsItsTimeTheNextAndWhatIsLeft) {
  RunCase run;
  ProbeMode mode(run.problem, run.scenario);
  const RunSummary s = run_scenario(mode, run.problem, run.scenario, run.x, {});
  EXPECT_EQ(s.termination, Termination::kCompleted);
  EXPECT_EQ(s.iterations, 6);
  ASSERT_EQ(mode.contexts.size(), 6u);
  const double t[] = {0.25, 0.5, 0.75, 1, 1, 1};
  for (int k = 0; k < 6; ++k) {
    const IterationContext& c = mode.contexts[k];
    EXPECT_EQ(c.t, t[k]) << k;
    EXPECT_EQ(c.iterations_left, 5 - k) << k;
    EXPECT_EQ(c.last(), k == 5);
    if (k < 5) {
      ASSERT_TRUE(c.next_t.has_value());
      EXPECT_EQ(*c.next_t, t[k + 1]);
    } else {
      EXPECT_FALSE(c.next_t.has_value());
    }
  }
}

TEST(Run, DiagnosticsAreMeasuredOnTheFineProblemWithTheFinalTargetsToo) {
  RunCase run;
  ProbeMode mode(run.problem, run.scenario);
  const IterationReport r = run_iteration(mode, run.problem, run.scenario, run.x, 1, 5);
  EXPECT_EQ(r.iteration, 1);
  EXPECT_EQ(r.mode, "standard");
  EXPECT_EQ(r.t, 0.25);
  EXPECT_EQ(r.step.work.steps, 1);
  // The diagnostics of the state after the iteration, with the targets of t = 0.25 ...
  EXPECT_EQ(r.diagnostics.objective, diagnose(run.problem, run.x).objective);
  // ... and the objective against the targets of t = 1, which the run leaves at t = 0.25.
  DogProblem final_targets(model().fine, model().fine_topology);
  run.scenario.install(final_targets);
  run.scenario.apply(final_targets, 1.0);
  EXPECT_EQ(r.objective_final_targets, weighted_objective(final_targets, run.x));
  EXPECT_GT(r.objective_final_targets, r.diagnostics.objective);
  EXPECT_EQ(run.problem.positions.target(1),
            run.scenario.positions[1].start +
                0.25 * (run.scenario.positions[1].end - run.scenario.positions[1].start));
}

TEST(Run, AFailedIterationEndsTheRunAndNamesIt) {
  RunCase run;
  ProbeMode mode(run.problem, run.scenario);
  mode.fail_at = 3;
  const RunSummary s = run_scenario(mode, run.problem, run.scenario, run.x, {});
  EXPECT_EQ(s.termination, Termination::kFailed);
  EXPECT_TRUE(s.failed());
  EXPECT_EQ(s.iterations, 2);
  EXPECT_EQ(s.failure, "iteration 3: asked to fail");
  EXPECT_STREQ(enum_name(s.termination), "failed");
}

// A state beyond kDivergedDogResidual is a failed iteration, which leaves x as it found it: for a
// run, and for one iteration at a time (the studio's session).
TEST(Run, ADivergedIterationFailsAndLeavesThePositions) {
  RunCase run;
  ProbeMode mode(run.problem, run.scenario);
  mode.diverge_at = 3;
  const RunSummary s = run_scenario(mode, run.problem, run.scenario, run.x, {});
  EXPECT_EQ(s.termination, Termination::kFailed);
  EXPECT_EQ(s.iterations, 2);
  EXPECT_EQ(s.failure.rfind("iteration 3: the state diverged (DOG residual ", 0), 0u) << s.failure;
  EXPECT_GT(s.last.diagnostics.dog_max, kDivergedDogResidual);
  EXPECT_NEAR(run.x[2], 0.02, 1e-15);  // two good iterations, not the third

  RunCase one;
  ProbeMode single(one.problem, one.scenario);
  single.diverge_at = 1;
  const Dofs x0 = one.x;
  const IterationReport r =
      run_iteration(single, one.problem, one.scenario, one.x, 1, IterationContext::kOpenEnded);
  EXPECT_TRUE(r.step.failed);
  EXPECT_TRUE(one.x == x0);
}

TEST(Run, ARaisedCancelFlagEndsTheRunBeforeTheNextIteration) {
  RunCase run;
  std::atomic<bool> cancel{false};
  ProbeMode mode(run.problem, run.scenario);
  mode.cancel_after = 2;
  mode.cancel = &cancel;
  const RunSummary s = run_scenario(mode, run.problem, run.scenario, run.x, {}, &cancel);
  EXPECT_EQ(s.termination, Termination::kCancelled);
  EXPECT_EQ(s.iterations, 2);
  EXPECT_FALSE(s.failed());
  EXPECT_STREQ(enum_name(s.termination), "cancelled");
}

TEST(Run, TheScheduleSwitchesModes) {
  RunCase run;
  ProbeMode first(run.problem, run.scenario), second(run.problem, run.scenario);
  auto schedule = [&](int k, const Dofs&) -> Mode* { return k == 3 ? &second : nullptr; };
  run_scenario(first, run.problem, run.scenario, run.x, {}, nullptr, schedule);
  EXPECT_EQ(first.contexts.size(), 2u);
  EXPECT_EQ(second.contexts.size(), 4u);
}

}  // namespace
}  // namespace sdog
