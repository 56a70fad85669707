// The experiments of sdog bench and sdog compare (case_rounds.h): cases run in rounds, cases that
// cannot run recorded or thrown, and the ratios to the standard mode.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "base/csv.h"
#include "base/errors.h"
#include "base/statistics.h"
#include "solver/experiments/case_rounds.h"
#include "solver/experiments/tables.h"
#include "tests/solver/run_recorder.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

// Records which mode ran each iteration, in the order the iterations came.
struct ModeLog : RunObserver {
  std::vector<std::pair<std::string, int>> order;  // (mode, iteration)
  void on_iteration(const IterationReport& r, const Dofs&) override {
    order.push_back({r.mode, r.iteration});
  }
};

TEST(CaseRounds, RoundsRunEveryModeOnceBeforeTheNextRound) {
  RunConfig config = test::short_run(4, 1);
  const std::string pattern = test::dataset("one_curve.svg");
  const std::vector<Case> cases = {{pattern, "15x11", ModeKind::kStandard},
                                   {pattern, "15x11", ModeKind::kSubsolvers}};
  ModeLog log;
  std::vector<std::pair<std::string, int>> runs;  // (mode, round) as the runs began
  RoundsOptions options;
  options.repeat = 3;
  options.observers = [&](const Case& c, int round) {
    runs.push_back({enum_name(c.mode), round});
    return std::vector<RunObserver*>{&log};
  };
  const auto rows = run_rounds(cases, config, options);
  const std::vector<std::pair<std::string, int>> expected = {{"standard", 0}, {"subsolvers", 0},
                                                             {"standard", 1}, {"subsolvers", 1},
                                                             {"standard", 2}, {"subsolvers", 2}};
  EXPECT_EQ(runs, expected);
  // The iterations themselves came in that order: five per run, one run after another.
  ASSERT_EQ(log.order.size(), 6u * 5);
  for (size_t k = 0; k < expected.size(); ++k)
    for (int i = 0; i < 5; ++i) {
      EXPECT_EQ(log.order[5 * k + i].first, expected[k].first) << "run " << k;
      EXPECT_EQ(log.order[5 * k + i].second, i + 1) << "run " << k;
    }
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& r : rows) {
    EXPECT_TRUE(r.completed()) << r.note;
    EXPECT_EQ(r.round_ms.size(), 3u) << enum_name(r.mode);
    EXPECT_EQ(r.round_total_s.size(), 3u) << enum_name(r.mode);
    EXPECT_EQ(r.iterations, 5);
    EXPECT_EQ(r.series.size(), 5u);
    EXPECT_EQ(r.dof, 3 * r.vertices);
    EXPECT_LT(r.dog_max, 1e-4);
  }
  EXPECT_EQ(rows[0].mode, ModeKind::kStandard);
  EXPECT_EQ(rows[1].mode, ModeKind::kSubsolvers);
  // Related to the standard case as they come back.
  ASSERT_TRUE(rows[1].objective_ratio.has_value());
  EXPECT_DOUBLE_EQ(*rows[1].objective_ratio, rows[1].final_objective / rows[0].final_objective);
}

TEST(CaseRounds, AModeThatCannotRunIsSkippedAndTheOthersGoOn) {
  RunConfig config = test::short_run(3, 0);
  const std::string pattern = test::dataset("one_curve.svg");
  // Even resolutions have no nested coarse mesh: the coarse mode cannot run them.
  const std::vector<Case> cases = {{pattern, "14x10", ModeKind::kCoarse},
                                   {pattern, "14x10", ModeKind::kStandard}};
  int coarse_runs = 0;
  RoundsOptions options;
  options.repeat = 2;
  options.observers = [&](const Case& c, int) {
    coarse_runs += c.mode == ModeKind::kCoarse;
    return std::vector<RunObserver*>{};
  };
  const auto rows = run_rounds(cases, config, options);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].status, CaseStatus::kSkipped);
  EXPECT_FALSE(rows[0].note.empty());
  EXPECT_EQ(coarse_runs, 0);
  EXPECT_TRUE(rows[1].completed()) << rows[1].note;
  EXPECT_EQ(rows[1].round_ms.size(), 2u);
  // The bench does not record it: the error reaches the caller.
  options.record_problems = false;
  EXPECT_THROW(run_rounds(cases, config, options), UsageError);
}

TEST(CaseRounds, AFailingRunIsRecordedOrThrown) {
  RunConfig config = test::short_run(3, 0);
  config.scenario = ScenarioKind::kNone;
  PositionSpec nowhere;  // a target that is not a number: the first iteration fails
  nowhere.vertex = 0;
  nowhere.end = Eigen::Vector3d(std::nan(""), 0, 0);
  config.positions.push_back(nowhere);
  const std::vector<Case> cases = {{test::dataset("one_curve.svg"), "15x11", ModeKind::kStandard}};
  RoundsOptions options;
  options.repeat = 2;
  const auto rows = run_rounds(cases, config, options);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].status, CaseStatus::kFailed);
  EXPECT_NE(rows[0].note.find("iteration 1"), std::string::npos) << rows[0].note;
  EXPECT_EQ(rows[0].round_ms.size(), 1u);  // no second round
  options.record_problems = false;
  EXPECT_THROW(run_rounds(cases, config, options), SolverError);
}

CaseResult timed_row(ModeKind mode, std::vector<double> round_ms) {
  CaseResult r;
  r.pattern = "p";
  r.res = "9x9";
  r.mode = mode;
  r.final_objective = 1;
  r.total_s = 1;
  r.round_ms = std::move(round_ms);
  r.median_ms = median(r.round_ms);
  return r;
}

TEST(CaseRounds, PairedSpeedupIsTheMedianOfTheRoundsRatios) {
  // Round ratios 4, 2.5 and 2: their median is 2.5, while the ratio of the medians is 200 / 100
  // = 2.
  std::vector<CaseResult> rows = {timed_row(ModeKind::kStandard, {400, 100, 200}),
                                  timed_row(ModeKind::kTwoLevel, {100, 40, 100})};
  relate_to_standard(rows);
  ASSERT_TRUE(rows[1].speedup && rows[1].speedup_paired);
  EXPECT_DOUBLE_EQ(*rows[1].speedup, 2.0);
  EXPECT_DOUBLE_EQ(*rows[1].speedup_paired, 2.5);
  EXPECT_DOUBLE_EQ(*rows[0].speedup_paired, 1.0);
  // Without a full set of rounds to pair (a run that failed in round 2) there is no paired ratio.
  rows[1].round_ms.pop_back();
  relate_to_standard(rows);
  EXPECT_TRUE(rows[1].speedup.has_value());
  EXPECT_FALSE(rows[1].speedup_paired.has_value());
  // Without a standard result there is nothing to relate to.
  std::vector<CaseResult> alone = {timed_row(ModeKind::kTwoLevel, {100})};
  relate_to_standard(alone);
  EXPECT_FALSE(alone[0].speedup.has_value());
}

TEST(CaseTables, SkippedCasesHaveOnlyTheirNamesStatusAndNote) {
  CaseResult r = timed_row(ModeKind::kCoarse, {1});
  r.status = CaseStatus::kSkipped;
  r.note = "needs, the coarse mesh";
  const auto fields = compare_fields(r);
  ASSERT_EQ(fields.size(), compare_columns().size());
  EXPECT_EQ(fields[2], "coarse");
  for (size_t i = 3; i + 2 < fields.size(); ++i) EXPECT_EQ(fields[i], "") << compare_columns()[i];
  EXPECT_EQ(fields[fields.size() - 2], "skipped");
  const std::string line = csv_line(fields);
  EXPECT_NE(line.find(",skipped,\"needs, the coarse mesh\"\n"), std::string::npos) << line;
  EXPECT_EQ(bench_fields(timed_row(ModeKind::kStandard, {2})).size(), bench_columns().size());
}

}  // namespace
}  // namespace sdog
