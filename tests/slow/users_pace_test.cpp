// The corners drag at a user's pace on the thesis's parallel_curves_4 at 39x65 (label slow): the
// final targets reached after 10 iterations, then held until converged and one last iteration,
// as `sdog bench --pace` runs it. The run ends converged, within the final tolerance and folded:
// the last iteration's steps from a converged folded state never trade it for an unfolded one of
// lower objective. Reads the pattern from ../shared/reference and skips without it.
#include <gtest/gtest.h>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/experiments/pace.h"
#include "solver/run/run_config.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

TEST(UsersPace, ParallelCurvesEndsFoldedAfterATenIterationDrag) {
  SDOG_REQUIRE_SHARED();
  const DogModel model = build_dog_model(
      read_crease_pattern(test::reference_patterns_dir() + "/parallel_curves_4.svg"), {39, 65});
  const PaceResult r = run_pace(model, RunConfig{}, 10, 200);
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_TRUE(r.converged);
  EXPECT_TRUE(r.folded);
  EXPECT_LE(r.dog_max, 5e-7);
  EXPECT_LE(r.stitch_gap_max, 5e-7);
  RecordProperty("final_objective", std::to_string(r.objective));
}

}  // namespace
}  // namespace sdog
