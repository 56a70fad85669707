// Table 6.1 of the thesis: fine vertex counts and patch counts from the reference crease patterns.
#include <gtest/gtest.h>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

struct ThesisCase {
  const char* pattern;
  int nx, ny, vertices, patches;
  friend void PrintTo(const ThesisCase& c, std::ostream* os) {
    *os << c.pattern << " " << c.nx << "x" << c.ny;
  }
};

const ThesisCase kCases[] = {
    {"1_curve", 31, 21, 721, 2},
    {"1_curve", 43, 31, 1435, 2},
    {"1_curve", 55, 41, 2389, 2},
    {"1_curve", 81, 59, 4969, 2},
    {"4_corners", 21, 21, 569, 5},
    {"4_corners", 41, 41, 1937, 5},
    {"4_corners", 61, 61, 4105, 5},
    {"4_corners", 81, 81, 7073, 5},
    {"valley", 21, 21, 639, 6},
    {"valley", 41, 41, 2069, 6},
    {"valley", 61, 61, 4301, 6},
    {"valley", 81, 81, 7327, 6},
    {"parallel_curves_4", 27, 45, 1498, 5},
    {"parallel_curves_4", 39, 65, 2943, 5},
    {"parallel_curves_4", 45, 75, 3847, 5},
    {"parallel_curves_4", 51, 85, 4867, 5},
};

class ThesisCounts : public ::testing::TestWithParam<ThesisCase> {};

TEST_P(ThesisCounts, FineVertexAndPatchCountsMatchTable61) {
  SDOG_REQUIRE_SHARED();
  const ThesisCase& c = GetParam();
  const auto pattern =
      read_crease_pattern(test::reference_patterns_dir() + "/" + c.pattern + ".svg");
  const DogModel m = build_dog_model(pattern, {c.nx, c.ny});
  EXPECT_EQ(m.fine.vertex_count(), c.vertices);
  EXPECT_EQ(m.fine.patch_count(), c.patches);
  EXPECT_EQ(m.coarse.patch_count(), c.patches);
}

INSTANTIATE_TEST_SUITE_P(Table61, ThesisCounts, ::testing::ValuesIn(kCases), [](const auto& info) {
  return std::string(info.param.pattern) + "_" + std::to_string(info.param.nx) + "x" +
         std::to_string(info.param.ny);
});

}  // namespace
}  // namespace sdog
