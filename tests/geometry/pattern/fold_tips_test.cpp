// Fold tips (geometry/pattern/fold_tips.h): two creases ending together inside the sheet at an
// angle.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "geometry/pattern/crease_pattern.h"
#include "geometry/pattern/fold_tips.h"
#include "geometry/pattern/pattern_cleaning.h"
#include "tests/geometry/pattern_builders.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

using test::rectangle_pattern;

// Creases from the bottom edge to (50, 60) and from there on, with the given assignments; a third
// crease from the top edge to (50, 60) when `third`.
CleanPattern meeting(const Polyline2& second, Fold a, Fold b, bool third = false) {
  std::vector<Polyline2> creases{{{50, 0}, {50, 60}}, second};
  if (third) creases.push_back({{20, 100}, {50, 60}});
  CreasePattern p = rectangle_pattern(100, 100, creases);
  p.creases[0].fold = a;
  p.creases[1].fold = b;
  if (third) p.creases[2].fold = Fold::kMountain;
  return clean_pattern(p);
}

TEST(FoldTips, AMountainAndAValleyEndingTogetherAtAnAngleMakeOne) {
  // The second crease leaves (50, 60) towards (80, 0): 3:6 against straight down, atan(0.5).
  const std::vector<FoldTip> tips =
      fold_tips(meeting({{50, 60}, {80, 0}}, Fold::kMountain, Fold::kValley));
  ASSERT_EQ(tips.size(), 1u);
  EXPECT_EQ(tips[0].point, Eigen::Vector2d(50, 60));
  EXPECT_EQ(tips[0].creases, (std::array<int, 2>{0, 1}));
  EXPECT_NEAR(tips[0].angle_degrees, std::atan(0.5) * 180 / M_PI, 1e-9);
}

TEST(FoldTips, CreasesThatContinueEachOtherOrMeetAThirdMakeNone) {
  // Straight on to the top edge: a mountain turning into a valley along one line.
  EXPECT_TRUE(fold_tips(meeting({{50, 60}, {50, 100}}, Fold::kMountain, Fold::kValley)).empty());
  // Within kStraightCreaseDegrees of straight.
  const double off = 40 * std::tan(0.5 * kStraightCreaseDegrees * M_PI / 180);
  EXPECT_TRUE(
      fold_tips(meeting({{50, 60}, {50 + off, 100}}, Fold::kMountain, Fold::kValley)).empty());
  // Both flat: nothing folds there.
  EXPECT_TRUE(fold_tips(meeting({{50, 60}, {80, 0}}, Fold::kFlat, Fold::kFlat)).empty());
  // A third crease ending there makes a degree-3 vertex.
  EXPECT_TRUE(
      fold_tips(meeting({{50, 60}, {80, 0}}, Fold::kMountain, Fold::kValley, true)).empty());
}

TEST(FoldTips, TheVPleatHasOneAndPatternsWithoutInnerEndsNone) {
  // datasets/v_pleat.fold: edges 6 (mountain) and 22 (valley) leave the vertex (50, 38) towards
  // (47.18, 41.523) and (52.82, 41.523).
  const CleanPattern v = clean_pattern(read_crease_pattern(test::dataset("v_pleat.fold")));
  const std::vector<FoldTip> tips = fold_tips(v);
  ASSERT_EQ(tips.size(), 1u);
  EXPECT_NEAR(std::abs(tips[0].point.x()), 50, 1e-9);
  EXPECT_NEAR(std::abs(tips[0].point.y()), 38, 1e-9);
  EXPECT_NEAR(tips[0].angle_degrees, 2 * std::atan(2.82 / 3.523) * 180 / M_PI, 1e-6);
  for (const char* name : {"curved_pleats.svg", "crossing_wave_pleats.svg", "four_corner_arcs.svg",
                           "zigzag_pleats.fold", "crossing_creases.svg"})
    EXPECT_TRUE(fold_tips(clean_pattern(read_crease_pattern(test::dataset(name)))).empty()) << name;
}

TEST(FoldTips, TheModelWarnsNamingBothCreasesAndKeepsTheTipInMeshUnits) {
  const DogModel m = build_dog_model(read_crease_pattern(test::dataset("v_pleat.fold")),
                                     parse_resolution("21x21"));
  ASSERT_EQ(m.fine.fold_tips.size(), 1u);
  // The sheet is 100 units wide on 20 grid edges.
  EXPECT_NEAR(m.fine.fold_tips[0].x(), 10, 1e-9);
  int warned = 0;
  for (const std::string& w : model_warnings(m))
    if (w.find("end together") != std::string::npos) {
      ++warned;
      EXPECT_NE(w.find("creases 0 (" + m.clean.creases[0].origin + ") and 1 (" +
                       m.clean.creases[1].origin + ")"),
                std::string::npos)
          << w;
    }
  EXPECT_EQ(warned, 1);
}

}  // namespace
}  // namespace sdog
