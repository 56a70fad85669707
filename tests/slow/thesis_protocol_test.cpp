// The eight thesis runs of the standard solver (the corners protocol at the thesis's resolutions 1
// and 2, 300 iterations each; label slow): the constraint bars after every iteration and at the
// end, folded, and a final objective at most 15% above the thesis's. They read the thesis patterns
// from ../shared/reference and skip without it.
#include <gtest/gtest.h>

#include <string>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/run/run_config.h"
#include "tests/solver/run_recorder.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

using test::RunResult;

struct ThesisCase {
  std::string pattern;
  int nx, ny;
  double thesis_objective;  // ../shared/reference/thesis-results.md, Figure 6.2, standard
  friend void PrintTo(const ThesisCase& c, std::ostream* os) {
    *os << c.pattern << "_" << c.nx << "x" << c.ny;
  }
};

class ThesisProtocol : public ::testing::TestWithParam<ThesisCase> {};

TEST_P(ThesisProtocol, MeetsTheConstraintBarsAndTheThesisObjective) {
  SDOG_REQUIRE_SHARED();
  const ThesisCase& c = GetParam();
  const DogModel model = build_dog_model(
      read_crease_pattern(test::reference_patterns_dir() + "/" + c.pattern + ".svg"), {c.nx, c.ny});
  const RunResult r = test::run_mode("standard", model, test::thesis_config());
  ASSERT_FALSE(r.summary.failed()) << r.summary.failure;
  ASSERT_EQ(r.summary.iterations, 300);
  for (const auto& rep : r.reports)
    EXPECT_LT(rep.diagnostics.dog_max, 1e-4) << "iteration " << rep.iteration;
  EXPECT_LT(r.reports.back().diagnostics.dog_max, 1e-6);
  EXPECT_TRUE(r.reports.back().step.folded);
  const double objective = r.reports.back().diagnostics.objective;
  // At most 15% above the thesis (a lower objective is a better local minimum); far below would
  // mean a different problem.
  EXPECT_LT(objective, 1.15 * c.thesis_objective);
  EXPECT_GT(objective, 0.7 * c.thesis_objective);
  RecordProperty("final_objective", std::to_string(objective));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ThesisProtocol,
    ::testing::Values(ThesisCase{"1_curve", 31, 21, 2.94}, ThesisCase{"1_curve", 43, 31, 3.00},
                      ThesisCase{"4_corners", 21, 21, 1.96}, ThesisCase{"4_corners", 41, 41, 2.53},
                      ThesisCase{"valley", 21, 21, 1.10}, ThesisCase{"valley", 41, 41, 1.42},
                      ThesisCase{"parallel_curves_4", 27, 45, 3.75},
                      ThesisCase{"parallel_curves_4", 39, 65, 4.50}));

}  // namespace
}  // namespace sdog
