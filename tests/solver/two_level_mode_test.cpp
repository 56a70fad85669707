// The twolevel mode (two_level_mode.h): fine DOG constraints every iteration with a report per
// patch, the coarse correction's effect on a drag compared with plain block Jacobi, and
// thread-count independence.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "geometry/dog_model.h"
#include "solver/mode_factory.h"
#include "tests/solver/run_recorder.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

const DogModel& model() {
  static const DogModel m = build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {21, 21});
  return m;
}

test::RunResult run(const std::string& mode, const RunConfig& config, int threads) {
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
  return test::run_mode(mode, model(), config);
}

TEST(TwoLevelMode, FollowsAngleConstraints) { test::expect_follows_angles("twolevel", model()); }

TEST(TwoLevelMode, KeepsTheFineDogConstraintsAndReportsEveryPatch) {
  const test::RunResult r = run("twolevel", test::short_run(12, 3), 2);
  ASSERT_FALSE(r.summary.failed) << r.summary.failure;
  test::expect_dog_and_patch_reports(r, model().fine.patch_count());
  EXPECT_LT(r.reports.back().diagnostics.dog_max, 1e-5);
  EXPECT_GT(r.reports.back().step.factorizations, model().fine.patch_count());  // the coarse step's too
}

// Block Jacobi hands the drag on by one patch per iteration: the dragged corner's patch tears away
// from the others. The coarse correction moves the whole sheet at once.
TEST(TwoLevelMode, TheCoarseCorrectionKeepsUpWithADrag) {
  const RunConfig config = test::short_run(100, 20);
  const test::RunResult two = run("twolevel", config, 2);
  const test::RunResult jacobi = run("subsolvers", config, 2);
  ASSERT_FALSE(two.summary.failed) << two.summary.failure;
  ASSERT_FALSE(jacobi.summary.failed) << jacobi.summary.failure;
  const Diagnostics& a = two.reports.back().diagnostics;
  const Diagnostics& b = jacobi.reports.back().diagnostics;
  EXPECT_LT(a.stitch_gap_max, 0.5 * b.stitch_gap_max);
  EXPECT_LT(a.objective, 0.8 * b.objective);
}

TEST(TwoLevelMode, SameResultWhateverTheThreadCount) {
  const RunConfig config = test::short_run(6, 0);
  EXPECT_TRUE(run("twolevel", config, 1).x == run("twolevel", config, 2).x);
}

}  // namespace
}  // namespace sdog
