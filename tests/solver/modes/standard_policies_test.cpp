// The standard mode's policies on their own: the fold-bias ladder, the sub-step schedule of
// continuation, convergence of held iterations without progress, and settling's bookkeeping and
// choice (fold_bias_ladder.h, substep_schedule.h, held_progress.h, settling_plan.h).
#include <gtest/gtest.h>

#include <vector>

#include "solver/modes/fold_bias_ladder.h"
#include "solver/modes/held_progress.h"
#include "solver/modes/settling_plan.h"
#include "solver/modes/substep_schedule.h"

namespace sdog {
namespace {

TEST(FoldBiasLadder, ClimbsByTenUpToTheCapAndReturnsToTheBase) {
  std::vector<double> installed;
  FoldBiasLadder ladder(0.5, 5000, [&](double w) { installed.push_back(w); });
  double weight = ladder.base();
  int rungs = 0;
  while (ladder.raise(weight)) ++rungs;
  EXPECT_EQ(rungs, 4);  // 5, 50, 500, 5000; 50000 would pass the cap
  EXPECT_EQ(installed, (std::vector<double>{5, 50, 500, 5000}));
  EXPECT_DOUBLE_EQ(weight, 5000);
  ladder.to_base();
  EXPECT_DOUBLE_EQ(installed.back(), 0.5);
  ladder.off();
  EXPECT_DOUBLE_EQ(installed.back(), 0);
  double zero = 0;
  EXPECT_FALSE(ladder.raise(zero)) << "folding off: no rungs";
}

TEST(FoldBiasLadder, AFailedClimbStopsTheIterationsLaterClimbs) {
  FoldBiasLadder ladder(1, 100, [](double) {});
  EXPECT_TRUE(ladder.may_climb());
  ladder.climb_failed();
  EXPECT_FALSE(ladder.may_climb());
  ladder.new_iteration();
  EXPECT_TRUE(ladder.may_climb());
}

TEST(SubstepSchedule, DoublesAfterAKeptStepAndHalvesAfterARejectedOne) {
  SubstepSchedule schedule(0.5);
  EXPECT_DOUBLE_EQ(schedule.next(10), 0.1) << "at most one largest sub-step of ten";
  EXPECT_DOUBLE_EQ(schedule.next(0.5), 1) << "never past the goal";
  schedule.rejected(0.1);
  EXPECT_DOUBLE_EQ(schedule.next(10), 0.05);
  schedule.rejected(0.05);
  EXPECT_DOUBLE_EQ(schedule.next(10), 0.025);
  schedule.kept();
  EXPECT_DOUBLE_EQ(schedule.next(10), 0.05);
  schedule.reset();
  EXPECT_DOUBLE_EQ(schedule.next(10), 0.1);
}

TEST(SubstepSchedule, KeepsLongStepsShortSubstepsAndTheSmallestButNoFailure) {
  SubstepSchedule schedule(0.5);
  EXPECT_TRUE(schedule.keeps(0.1, 10, false, 0.6));
  EXPECT_FALSE(schedule.keeps(0.1, 10, false, 0.4)) << "a line search that kept less than half";
  EXPECT_TRUE(schedule.keeps(0.02, 10, false, 0.1)) << "0.2 of the largest sub-step is short";
  EXPECT_TRUE(schedule.keeps(1.0 / 1024, 1000, false, 0.1)) << "the smallest sub-step is kept";
  EXPECT_FALSE(schedule.keeps(0.02, 10, true, 1)) << "a failed solve is never kept";
  EXPECT_TRUE(SubstepSchedule::short_move(0.25));
  EXPECT_FALSE(SubstepSchedule::short_move(0.26));
}

TEST(HeldProgress, ConvergesAfterFiveHeldIterationsWithoutProgress) {
  HeldProgress held(1e-3);
  EXPECT_TRUE(held.lowers(100));
  EXPECT_TRUE(held.lowers(99)) << "lower by more than 0.1%: progress";
  for (int k = 1; k < HeldProgress::kHeldWithoutProgress; ++k) EXPECT_TRUE(held.lowers(98.95)) << k;
  EXPECT_FALSE(held.lowers(98.95)) << "the fifth held iteration in a row without progress";
  held.reset();
  EXPECT_TRUE(held.lowers(98.95)) << "moved targets start the count again";
  EXPECT_TRUE(held.lowers(0.5)) << "a large decrease is progress";
  for (int k = 1; k < HeldProgress::kHeldWithoutProgress; ++k)
    EXPECT_TRUE(held.lowers(0.4995)) << k;
  EXPECT_FALSE(held.lowers(0.4995)) << "below 1 the margin is absolute (1e-3)";
}

TEST(SettlingPlan, SettlesAfterASecondGoalOrFromAGivenOriginElsewhere) {
  const Dofs origin = Dofs::Zero(6), moved = Dofs::Ones(6);
  SettlingPlan fresh(true, std::nullopt);
  fresh.begin_iteration(origin);
  fresh.new_goal();
  EXPECT_FALSE(fresh.wanted()) << "targets set once from the start: the straight path already";
  fresh.new_goal();
  EXPECT_TRUE(fresh.wanted());
  EXPECT_EQ(fresh.origin(), origin);
  fresh.done();
  EXPECT_FALSE(fresh.wanted());

  SettlingPlan studio(true, origin);  // a new mode after an edit, away from the session's start
  studio.begin_iteration(moved);
  studio.new_goal();
  EXPECT_TRUE(studio.wanted());
  EXPECT_EQ(studio.origin(), origin);
  studio.restart();
  studio.begin_iteration(origin);
  studio.new_goal();
  EXPECT_FALSE(studio.wanted()) << "restarted at its given origin";

  SettlingPlan off(false, origin);
  off.begin_iteration(moved);
  off.new_goal();
  off.new_goal();
  EXPECT_FALSE(off.wanted());
}

TEST(SettlingPlan, TheStraightFoldWinsWhenItIsFoldedAndAgreesBetterOrIsLower) {
  const SettledFold run{true, 2, 10.0};
  EXPECT_FALSE(straight_fold_wins(run, {false, 0, 1.0}, 0.01))
      << "an unfolded straight fold never wins";
  EXPECT_TRUE(straight_fold_wins(run, {true, 1, 20.0}, 0.01))
      << "fewer sites against their targets";
  EXPECT_FALSE(straight_fold_wins(run, {true, 3, 1.0}, 0.01)) << "more sites against their targets";
  EXPECT_TRUE(straight_fold_wins(run, {true, 2, 9.9}, 0.01))
      << "as many, lower by more than the margin";
  EXPECT_FALSE(straight_fold_wins(run, {true, 2, 9.995}, 0.01)) << "within the margin";
  EXPECT_TRUE(straight_fold_wins({false, 2, 1.0}, {true, 2, 20.0}, 0.01))
      << "the run's own fold is unfolded";
}

}  // namespace
}  // namespace sdog
