// The benchmark's rounds: every mode of a pattern and resolution runs once per round.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "solver/benchmark.h"
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

}  // namespace
}  // namespace sdog
