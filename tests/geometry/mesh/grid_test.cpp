#include <gtest/gtest.h>

#include "base/errors.h"
#include "geometry/mesh/grid.h"

namespace sdog {
namespace {

TEST(Resolution, ParsesBothFormsAndRejectsGarbage) {
  EXPECT_EQ(parse_resolution("31x21"), (Resolution{31, 21}));
  EXPECT_EQ(parse_resolution("41"), (Resolution{41, 41}));
  EXPECT_EQ(parse_resolution("7X9"), (Resolution{7, 9}));
  for (const char* bad : {"", "x", "31x", "x21", "3.5x7", "-3x7", "31x21x3", "abc", "9999999x3"})
    EXPECT_THROW(parse_resolution(bad), UsageError) << bad;
}

TEST(Resolution, IsCheckedForRangeAndParity) {
  EXPECT_NO_THROW(check_resolution({3, 3}, true));
  EXPECT_NO_THROW(check_resolution({2001, 2001}, true));
  EXPECT_THROW(check_resolution({2, 21}, false), UsageError);
  EXPECT_THROW(check_resolution({21, 2003}, false), UsageError);
  EXPECT_THROW(check_resolution({30, 21}, true), UsageError);
  EXPECT_NO_THROW(check_resolution({30, 20}, false));
  EXPECT_EQ(coarse_resolution({31, 21}), (Resolution{16, 11}));
}

// parallel_curves_4's sheet, 275 x 456, at 43x31: cells of 275 / 42 = 6.55 by 456 / 30 = 15.2,
// 2.3 times as tall as wide. With the 43 lines across kept, square cells need 42 * 456 / 275 =
// 69.6, so 70 cells (even, for an odd resolution): 43x71.
TEST(CellShape, WarnsAboutLongCellsAndNamesASquareResolution) {
  EXPECT_EQ(cell_shape_warning({41, 41}, 400, 400), "");
  EXPECT_EQ(cell_shape_warning({25, 41}, 275, 456), "");  // the automatic resolution
  const std::string tall = cell_shape_warning({43, 31}, 275, 456);
  EXPECT_NE(tall.find("2.3 times as tall as wide"), std::string::npos) << tall;
  EXPECT_NE(tall.find("43x31 on a sheet of 275 x 456"), std::string::npos) << tall;
  EXPECT_NE(tall.find("43x71"), std::string::npos) << tall;
  // 400 x 200 at 21x41: cells of 20 by 5; the 41 lines along the height stay, and 40 * 400 / 200
  // = 80 cells across.
  const std::string wide = cell_shape_warning({21, 41}, 400, 200);
  EXPECT_NE(wide.find("4 times as wide as tall"), std::string::npos) << wide;
  EXPECT_NE(wide.find("81x41"), std::string::npos) << wide;
  // The threshold, 1.5: cells of 10 by 14.9 pass, 10 by 15 do not.
  EXPECT_EQ(cell_shape_warning({31, 21}, 300, 298), "");
  EXPECT_NE(cell_shape_warning({31, 21}, 300, 300), "");
}

TEST(AxisLayout, WithoutPinsTheEndsAreTheOnlyAnchors) {
  const AxisLayout a = layout_axis(0, 10, 11, {});
  ASSERT_EQ(a.anchors.size(), 2u);
  EXPECT_EQ(a.anchors[0], (std::pair<int, double>{0, 0.0}));
  EXPECT_EQ(a.anchors[1], (std::pair<int, double>{10, 10.0}));
}

TEST(AxisLayout, PinTakesItsNearestLine) {
  // Uniform lines at 0, 1, ..., 10: 3.4 goes to line 3, 6.6 to line 7.
  const AxisLayout a = layout_axis(0, 10, 11, {6.6, 3.4});
  ASSERT_EQ(a.anchors.size(), 4u);
  EXPECT_EQ(a.anchors[1], (std::pair<int, double>{3, 3.4}));
  EXPECT_EQ(a.anchors[2], (std::pair<int, double>{7, 6.6}));
}

TEST(AxisLayout, PinsEqualUpToRoundingShareALine) {
  // Two junctions at one coordinate computed two ways (1e-12 apart) would make a row of width
  // 1e-12, where the solver's first step is not finite.
  const AxisLayout a = layout_axis(0, 10, 11, {3.4, 3.4 + 1e-12, 6.6});
  ASSERT_EQ(a.anchors.size(), 4u);
  EXPECT_EQ(a.anchors[1], (std::pair<int, double>{3, 3.4}));
  EXPECT_EQ(a.anchors[2], (std::pair<int, double>{7, 6.6}));
}

TEST(AxisLayout, CrowdedPinsKeepOrderOnDistinctLines) {
  // Three pins that all round to line 5 spread to lines 4..6 or 5..7 but keep their order.
  const AxisLayout a = layout_axis(0, 10, 11, {5.1, 4.9, 5.0});
  ASSERT_EQ(a.anchors.size(), 5u);
  for (size_t k = 1; k + 1 < a.anchors.size(); ++k) {
    EXPECT_LT(a.anchors[k - 1].first, a.anchors[k].first);
    EXPECT_LT(a.anchors[k - 1].second, a.anchors[k].second);
  }
  EXPECT_EQ(a.anchors[2].first, 5);  // the middle pin keeps its own line
}

TEST(AxisLayout, PinsNearTheEndStillLeaveRoom) {
  // Both pins round to line 10, the fixed end: they move down to lines 8 and 9, in order.
  const AxisLayout a = layout_axis(0, 10, 11, {9.95, 9.9});
  ASSERT_EQ(a.anchors.size(), 4u);
  EXPECT_EQ(a.anchors[1], (std::pair<int, double>{8, 9.9}));
  EXPECT_EQ(a.anchors[2], (std::pair<int, double>{9, 9.95}));
}

TEST(AxisLayout, TooManyPinsIsAUsageError) {
  EXPECT_THROW(layout_axis(0, 10, 4, {1, 2, 3}), UsageError);
  EXPECT_NO_THROW(layout_axis(0, 10, 5, {1, 2, 3}));
}

TEST(AxisLayout, PinsOnTheEndsNeedNoLine) {
  const AxisLayout a = layout_axis(0, 10, 3, {0.0, 10.0});
  EXPECT_EQ(a.anchors.size(), 2u);
}

TEST(AxisLayout, RefinementDoublesTheAnchorIndices) {
  const AxisLayout c = layout_axis(0, 10, 6, {4.1});
  const AxisLayout f = refine_axis(c);
  EXPECT_EQ(f.n, 11);
  ASSERT_EQ(f.anchors.size(), c.anchors.size());
  for (size_t k = 0; k < c.anchors.size(); ++k) {
    EXPECT_EQ(f.anchors[k].first, 2 * c.anchors[k].first);
    EXPECT_EQ(f.anchors[k].second, c.anchors[k].second);
  }
}

}  // namespace
}  // namespace sdog
