#include <gtest/gtest.h>

#include "geometry/pattern/pattern_cleaning.h"
#include "geometry/pattern/plane_geometry.h"
#include "tests/geometry/pattern_builders.h"

namespace sdog {
namespace {

TEST(PlaneGeometry, OrientationAndPointInPolygonAreExact) {
  const Polyline2 square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(point_in_polygon({0.5, 0.5}, square), 1);
  EXPECT_EQ(point_in_polygon({1.0, 0.3}, square), 0);
  EXPECT_EQ(point_in_polygon({1.0 + 1e-16 * 3, 0.3}, square), -1);
  EXPECT_EQ(orientation({0, 0}, {1, 1}, {0.1, 0.1}), 0);
  EXPECT_EQ(orientation({0, 0}, {1, 1}, {0.1, 0.1 + 1e-17}), 1);
  EXPECT_DOUBLE_EQ(signed_area(square), 1.0);
}

TEST(PlaneGeometry, FindsEveryContactBetweenPolylines) {
  const Polyline2 zigzag{{0, 0}, {1, 1}, {2, 0}, {3, 1}};
  const Polyline2 line{{0, 0.5}, {3, 0.5}};
  const auto contacts = find_segment_contacts({&zigzag, &line}, {false, false});
  ASSERT_EQ(contacts.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(contacts[k].a, 0);
    EXPECT_EQ(contacts[k].sa, k);
    EXPECT_EQ(contacts[k].b, 1);
  }
  // Consecutive segments of one polyline only count when they fold back.
  const Polyline2 fold{{0, 0}, {2, 0}, {1, 0}};
  EXPECT_EQ(find_segment_contacts({&fold}, {false}).size(), 1u);
}

TEST(PlaneGeometry, AHugeSegmentAmongManySmallOnesIsFoundQuickly) {
  // A found fuzz case: one segment spanning 1e50 units used to fill every bucket.
  Polyline2 wiggle;
  for (int k = 0; k <= 4000; ++k) wiggle.emplace_back(k * 0.01, (k % 2) * 0.01);
  const Polyline2 huge{{-1e50, 0.005}, {1e50, 0.005}};
  const auto contacts = find_segment_contacts({&wiggle, &huge}, {false, false});
  EXPECT_EQ(contacts.size(), 4000u);
}

TEST(PlaneGeometry, CleaningClipsCreasesReachingAbsurdlyFar) {
  const CleanPattern c = clean_pattern(
      test::rectangle_pattern(100, 100, {{{0, 50}, {50, 2.6e52}}, {{0, 20}, {100, 30}}}));
  ASSERT_EQ(c.creases.size(), 2u);
  for (const auto& crease : c.creases)
    for (const auto& p : crease.points) EXPECT_LE(std::abs(p.y()), 100.0);
}

}  // namespace
}  // namespace sdog
