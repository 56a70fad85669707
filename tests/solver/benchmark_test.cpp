// The benchmark's rounds (every mode of a pattern and resolution runs once per round) and its
// speedups over the standard mode.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "solver/experiments/benchmark.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

TEST(Benchmark, RoundsRunEveryModeOnceBeforeTheNextRound) {
  const std::string pattern = test::dataset("one_curve.svg");
  const std::vector<BenchCase> cases = {{pattern, "15x11", "standard"}, {pattern, "15x11", "subsolvers"}};
  BenchOptions options;
  options.iterations = 5;  // and a hold of 1
  options.repeat = 3;
  std::vector<std::pair<std::string, int>> runs;  // (mode, round) as the runs began
  int iterations = 0;
  const auto results = run_benchmark_rounds(cases, options, [&](const BenchCase& c, int round, int iteration, int total) {
    EXPECT_EQ(total, 6);
    ++iterations;
    if (iteration == 1) runs.push_back({c.mode, round});
  });
  const std::vector<std::pair<std::string, int>> expected = {{"standard", 0},   {"subsolvers", 0}, {"standard", 1},
                                                             {"subsolvers", 1}, {"standard", 2},   {"subsolvers", 2}};
  EXPECT_EQ(runs, expected);
  EXPECT_EQ(iterations, 6 * 6);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].mode, "standard");
  EXPECT_EQ(results[1].mode, "subsolvers");
  for (const auto& r : results) {
    ASSERT_EQ(r.run_medians.size(), 3u) << r.mode;
    EXPECT_EQ(r.median_ms, median(r.run_medians));
    EXPECT_GT(r.median_ms, 0);
    EXPECT_EQ(r.dof, 3 * r.vertices);
    EXPECT_LT(r.dog_max, 1e-4);
  }
}

TEST(Benchmark, SpeedupsAreRelativeToTheStandardRun) {
  BenchResult standard, other;
  standard.mode = "standard";
  standard.run_medians = {400, 100, 200};
  standard.median_ms = 200;
  other.mode = "twolevel";
  other.run_medians = {100, 40, 100};  // round ratios 4, 2.5 and 2
  other.median_ms = 100;
  std::vector<BenchResult> results = {other, standard};
  relate_bench_to_standard(results);
  ASSERT_TRUE(results[0].speedup && results[0].speedup_paired);
  EXPECT_DOUBLE_EQ(*results[0].speedup, 2.0);         // ratio of the medians
  EXPECT_DOUBLE_EQ(*results[0].speedup_paired, 2.5);  // median of the rounds' ratios
  EXPECT_DOUBLE_EQ(*results[1].speedup, 1.0);
  // Without a standard result there is nothing to relate to.
  std::vector<BenchResult> alone = {other};
  relate_bench_to_standard(alone);
  EXPECT_FALSE(alone[0].speedup.has_value());
  EXPECT_FALSE(alone[0].speedup_paired.has_value());
  // Rounds that do not pair up give no paired ratio.
  EXPECT_FALSE(paired_speedup({100, 200}, {50}).has_value());
  EXPECT_FALSE(paired_speedup({}, {}).has_value());
}

}  // namespace
}  // namespace sdog
