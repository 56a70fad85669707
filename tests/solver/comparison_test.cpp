// The comparison's rounds: every mode of a case runs once per round, and the paired speedup is the
// median of the rounds' ratios.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "solver/experiments/comparison.h"
#include "tests/solver/run_recorder.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

// Records which mode ran each iteration, in the order the iterations came.
struct ModeLog : RunObserver {
  std::vector<std::pair<std::string, int>> order;  // (mode, iteration)
  void on_iteration(const IterationReport& r, const Dofs&) override { order.push_back({r.mode, r.iteration}); }
};

TEST(Comparison, RoundsRunEveryModeOnceBeforeTheNextRound) {
  RunConfig config = test::short_run(4, 1);
  const std::string pattern = test::dataset("one_curve.svg");
  const std::vector<BenchCase> cases = {{pattern, "15x11", "standard"}, {pattern, "15x11", "subsolvers"}};
  ModeLog log;
  std::vector<std::pair<std::string, int>> runs;  // (mode, round) as the runs began
  const auto rows = run_compare_rounds(cases, config, 3, [&](const BenchCase& c, int round) {
    runs.push_back({c.mode, round});
    return std::vector<RunObserver*>{&log};
  });
  const std::vector<std::pair<std::string, int>> expected = {{"standard", 0},   {"subsolvers", 0}, {"standard", 1},
                                                             {"subsolvers", 1}, {"standard", 2},   {"subsolvers", 2}};
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
    ASSERT_EQ(r.round_ms.size(), 3u) << r.mode;
    EXPECT_EQ(r.median_ms, median(r.round_ms));
  }
  EXPECT_EQ(rows[0].mode, "standard");
  EXPECT_EQ(rows[1].mode, "subsolvers");
}

TEST(Comparison, AModeThatCannotRunIsSkippedAndTheOthersGoOn) {
  RunConfig config = test::short_run(3, 0);
  const std::string pattern = test::dataset("one_curve.svg");
  // Even resolutions have no nested coarse mesh: the coarse mode cannot run them.
  const std::vector<BenchCase> cases = {{pattern, "14x10", "coarse"}, {pattern, "14x10", "standard"}};
  int coarse_runs = 0;
  const auto rows = run_compare_rounds(cases, config, 2, [&](const BenchCase& c, int) {
    coarse_runs += c.mode == "coarse";
    return std::vector<RunObserver*>{};
  });
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].status, CompareStatus::Skipped);
  EXPECT_FALSE(rows[0].note.empty());
  EXPECT_EQ(coarse_runs, 0);
  EXPECT_TRUE(rows[1].completed()) << rows[1].note;
  EXPECT_EQ(rows[1].round_ms.size(), 2u);
}

CompareRow timed_row(const std::string& mode, std::vector<double> round_ms) {
  CompareRow r;
  r.pattern = "p";
  r.res = "9x9";
  r.mode = mode;
  r.final_objective = 1;
  r.total_s = 1;
  r.round_ms = std::move(round_ms);
  r.median_ms = median(r.round_ms);
  return r;
}

TEST(Comparison, PairedSpeedupIsTheMedianOfTheRoundsRatios) {
  // Round ratios 4, 2.5 and 2: their median is 2.5, while the ratio of the medians is 200 / 100 = 2.
  std::vector<CompareRow> rows = {timed_row("standard", {400, 100, 200}), timed_row("twolevel", {100, 40, 100})};
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
}

}  // namespace
}  // namespace sdog
