#include <gtest/gtest.h>

#include <algorithm>

#include "base/errors.h"
#include "geometry/mesh/dog_model.h"
#include "geometry/mesh/patch_layout.h"
#include "geometry/pattern/pattern_cleaning.h"
#include "geometry/pattern/pattern_faces.h"
#include "tests/geometry/pattern_builders.h"

namespace sdog {
namespace {

using test::rectangle_pattern;
using V2 = Eigen::Vector2d;

bool has_vertex(const Crease& c, const V2& p) {
  return std::find(c.points.begin(), c.points.end(), p) != c.points.end();
}

TEST(PatternCleaning, CreasePartsOutsideTheSheetAreClippedExactlyAtTheBoundary) {
  // Starts 3 units below the sheet, ends 5 units right of it.
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{20, -3}, {40, 50}, {105, 60}}}));
  ASSERT_EQ(c.creases.size(), 1u);
  const auto& pts = c.creases[0].points;
  EXPECT_EQ(pts.front().y(), 0.0);
  EXPECT_EQ(pts.back().x(), 100.0);
  EXPECT_NEAR(pts.front().x(), 20 + 20 * 3.0 / 53, 1e-12);
  // The ends became boundary vertices.
  EXPECT_NE(std::find(c.sheet.outer.begin(), c.sheet.outer.end(), pts.front()),
            c.sheet.outer.end());
  EXPECT_NE(std::find(c.sheet.outer.begin(), c.sheet.outer.end(), pts.back()), c.sheet.outer.end());
  EXPECT_TRUE(c.pins.empty()) << "ends on the bounding box need no pins";
}

TEST(PatternCleaning, EndsShortOfTheBoundarySnapOntoIt) {
  // L = 100: snapping reaches 2 units.
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{1.5, 40}, {50, 60}, {98.5, 70}}}));
  EXPECT_EQ(c.creases[0].points.front(), V2(0, 40));
  EXPECT_EQ(c.creases[0].points.back(), V2(100, 70));
}

TEST(PatternCleaning, ACreaseEndingInsideTheSheetIsContinuedByASeamToTheBoundary) {
  // Ends at (50, 60), 40 units from the boundary: a seam continues its last segment's direction
  // (3, 2) to the right edge at (100, 93.33).
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{0, 40}, {20, 40}, {50, 60}}}));
  ASSERT_EQ(c.creases.size(), 2u);
  EXPECT_EQ(c.creases[0].kind, CurveKind::kCrease);
  const Crease& seam = c.creases[1];
  EXPECT_EQ(seam.kind, CurveKind::kSeam);
  EXPECT_EQ(seam.fold, Fold::kFlat);
  ASSERT_EQ(seam.points.size(), 2u);
  EXPECT_EQ(seam.points.front(), V2(50, 60));
  EXPECT_EQ(seam.points.back().x(), 100.0);
  EXPECT_NEAR(seam.points.back().y(), 60 + 50 * 2.0 / 3, 1e-9);
  EXPECT_NE(std::find(c.sheet.outer.begin(), c.sheet.outer.end(), seam.points.back()),
            c.sheet.outer.end());
  ASSERT_EQ(c.junctions.size(), 1u);
  EXPECT_EQ(c.junctions[0], V2(50, 60));
  ASSERT_EQ(c.warnings.size(), 1u);
  for (const char* part : {"crease 0", "ends inside the sheet at (50, 60)", "fold fades to flat",
                           "seam", "the sheet boundary at (100, 93.33"})
    EXPECT_NE(c.warnings[0].find(part), std::string::npos) << c.warnings[0];
  EXPECT_EQ(count_pattern_patches(c), 2);
}

TEST(PatternCleaning, ASeamEndsOnTheFirstCreaseItMeetsAndAnInteriorCreaseGetsTwo) {
  // Crease 1 lies inside the sheet, both ends far from everything: one seam runs left to the
  // boundary, the other right until it meets crease 0 (a T junction there).
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{80, 0}, {80, 100}}, {{20, 50}, {40, 50}}}));
  ASSERT_EQ(c.creases.size(), 4u);
  std::vector<Polyline2> seams;
  for (const Crease& k : c.creases)
    if (k.kind == CurveKind::kSeam) seams.push_back(k.points);
  ASSERT_EQ(seams.size(), 2u);
  EXPECT_EQ(seams[0], (Polyline2{V2(20, 50), V2(0, 50)}));
  EXPECT_EQ(seams[1], (Polyline2{V2(40, 50), V2(80, 50)}));
  EXPECT_TRUE(has_vertex(c.creases[0], V2(80, 50))) << "the seam's end is a vertex of crease 0";
  EXPECT_EQ(count_pattern_patches(c), 3);
}

TEST(PatternCleaning, WithoutSeamsACreaseEndingInsideTheSheetIsRejectedWithItsPosition) {
  CleaningOptions no_seams;
  no_seams.seams = false;
  try {
    clean_pattern(rectangle_pattern(100, 100, {{{0, 40}, {50, 60}}}), no_seams);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("crease 0"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(50, 60)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("must end on the boundary"), std::string::npos) << msg;
  }
}

TEST(PatternCleaning, CrossingCreasesShareOneJunctionVertex) {
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{0, 30}, {100, 70}}, {{20, 0}, {60, 100}}}));
  ASSERT_EQ(c.junctions.size(), 1u);
  const V2 j = c.junctions[0];
  EXPECT_TRUE(has_vertex(c.creases[0], j));
  EXPECT_TRUE(has_vertex(c.creases[1], j));
  // y = 30 + 0.4 x meets x = 20 + 0.4 y at y = 38 / 0.84.
  EXPECT_NEAR(j.y(), 38 / 0.84, 1e-9);
  EXPECT_NEAR(j.x(), 20 + 0.4 * 38 / 0.84, 1e-9);
  EXPECT_EQ(c.pins.size(), 1u);
  EXPECT_EQ(count_pattern_patches(c), 4);
}

TEST(PatternCleaning, NearlyConcurrentCreasesMergeIntoOneJunction) {
  // Three lines whose pairwise crossings lie within 0.5 of (50, 50) (L/100 = 1).
  const CleanPattern c = clean_pattern(rectangle_pattern(
      100, 100, {{{0, 50}, {100, 50.4}}, {{50, 0}, {50.3, 100}}, {{0, 0.2}, {100, 100}}}));
  ASSERT_EQ(c.junctions.size(), 1u);
  for (const auto& crease : c.creases) EXPECT_TRUE(has_vertex(crease, c.junctions[0]));
  EXPECT_EQ(count_pattern_patches(c), 6);
}

TEST(PatternCleaning, EndNearACreaseMakesATJunction) {
  // The second crease stops 1.5 units short of the first (within L/50 = 2).
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{0, 50}, {100, 50}}, {{40, 0}, {40, 48.5}}}));
  ASSERT_EQ(c.junctions.size(), 1u);
  EXPECT_EQ(c.junctions[0], V2(40, 50));
  EXPECT_TRUE(has_vertex(c.creases[0], V2(40, 50)));
  EXPECT_EQ(c.creases[1].points.back(), V2(40, 50));
  EXPECT_EQ(count_pattern_patches(c), 3);
}

TEST(PatternCleaning, PiecesMeetingEndToEndAreJoined) {
  // One crease drawn as two pieces whose ends are 0.5 apart (L/100 = 1).
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{0, 50}, {50, 60}}, {{50.5, 60}, {100, 50}}}));
  ASSERT_EQ(c.creases.size(), 1u);
  EXPECT_TRUE(c.junctions.empty());
  EXPECT_EQ(c.creases[0].points.front(), V2(0, 50));
  EXPECT_EQ(c.creases[0].points.back(), V2(100, 50));
}

TEST(PatternCleaning, ClosedCreaseInsideStaysClosed) {
  Polyline2 circle;
  for (int k = 0; k < 64; ++k)
    circle.emplace_back(50 + 20 * std::cos(k * M_PI / 32), 50 + 20 * std::sin(k * M_PI / 32));
  const CleanPattern c = clean_pattern(rectangle_pattern(100, 100, {circle}, {true}));
  ASSERT_EQ(c.creases.size(), 1u);
  EXPECT_TRUE(c.creases[0].closed);
  EXPECT_EQ(count_pattern_patches(c), 2);
}

TEST(PatternCleaning, CreasePartAlongTheBoundaryIsDroppedWithAWarning) {
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{0, 0}, {100, 0}, {100, 50}, {0, 60}}}));
  ASSERT_EQ(c.creases.size(), 1u);
  EXPECT_EQ(c.creases[0].points, (Polyline2{{100, 50}, {0, 60}}));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("crease 0"), std::string::npos) << c.warnings[0];
  EXPECT_NE(c.warnings[0].find("along the sheet boundary (2 segment(s))"), std::string::npos)
      << c.warnings[0];
}

TEST(PatternCleaning, CreaseWhollyOnTheBoundaryDisappears) {
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{0, 100}, {40, 100}}, {{50, 0}, {50, 100}}}));
  ASSERT_EQ(c.creases.size(), 1u);
  EXPECT_EQ(c.creases[0].points.front().x(), 50);
  EXPECT_EQ(c.warnings.size(), 1u);
}

TEST(PatternCleaning, CreaseDrawnTwiceIsMergedWithAWarning) {
  CreasePattern p = rectangle_pattern(
      100, 100, {{{50, 0}, {50, 100}}, {{50, 100}, {50, 0}}, {{0, 50}, {50, 50}}});
  p.creases[0].fold = Fold::kMountain;
  p.creases[1].fold = Fold::kValley;
  const CleanPattern c = clean_pattern(p);
  ASSERT_EQ(c.creases.size(), 2u);
  EXPECT_EQ(c.creases[0].fold, Fold::kMountain) << "the first drawing wins";
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("crease 1"), std::string::npos) << c.warnings[0];
  EXPECT_NE(c.warnings[0].find("valley dropped for mountain"), std::string::npos) << c.warnings[0];
}

TEST(PatternCleaning, CreaseDrawnPartlyAgainKeepsItsOwnPart) {
  // The second crease repeats the first one's lower half, then turns right: its turn is kept and
  // ends on the first crease (a T junction).
  const CleanPattern c = clean_pattern(
      rectangle_pattern(100, 100, {{{50, 0}, {50, 100}}, {{50, 0}, {50, 40}, {100, 40}}}));
  ASSERT_EQ(c.creases.size(), 2u);
  EXPECT_EQ(c.creases[1].points, (Polyline2{{50, 40}, {100, 40}}));
  EXPECT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(count_pattern_patches(c), 3);
}

TEST(PatternCleaning, NearbyJunctionCoordinatesAreAligned) {
  // T junctions at (30, 30) and (31.5, 70): x within L/50 = 2, so both move to x = 30.75 and
  // the grid needs one line for them.
  const CleanPattern c = clean_pattern(rectangle_pattern(100, 100,
                                                         {{{0, 30}, {100, 30}},
                                                          {{0, 70}, {100, 70}},
                                                          {{30, 0}, {30, 30}},
                                                          {{31.5, 70}, {31.5, 100}}}));
  ASSERT_EQ(c.junctions.size(), 2u);
  EXPECT_EQ(c.junctions[0].x(), 30.75);
  EXPECT_EQ(c.junctions[1].x(), 30.75);
  EXPECT_EQ(count_pattern_patches(c), 5);
}

TEST(PatternCleaning, RefusesInvalidOptions) {
  CleaningOptions o;
  o.snap_fraction = -1;
  EXPECT_FALSE(o.validate().empty());
  EXPECT_THROW(clean_pattern(rectangle_pattern(100, 100), o), UsageError);
}

}  // namespace
}  // namespace sdog

namespace sdog {
namespace {

CreasePattern annulus_pattern(std::vector<Polyline2> creases) {
  CreasePattern p = test::rectangle_pattern(100, 80, std::move(creases));
  p.sheet.holes = {{{40, 30}, {40, 50}, {60, 50}, {60, 31}}};
  return p;
}

TEST(NonSeparatingCreases, FromTheBoundaryToAHole) {
  const CleanPattern c = clean_pattern(annulus_pattern({{{50, 0}, {50, 30.5}}}));
  EXPECT_EQ(first_non_separating_crease(c), 0);
}

TEST(NonSeparatingCreases, FromACreaseToAHole) {
  // The second piece of the slanted crease (after the crossing at x = 80) runs from the vertical
  // crease to the hole: the piece left of x = 80 stays one ring around the hole.
  const CleanPattern c =
      clean_pattern(annulus_pattern({{{100, 80}, {40, 50}}, {{80, 0}, {80, 80}}}));
  ASSERT_EQ(c.creases[0].points.size(), 3u) << "one crease through the crossing";
  EXPECT_EQ(first_non_separating_crease(c), 0);
}

TEST(NonSeparatingCreases, SeparatingCreasesPass) {
  EXPECT_EQ(first_non_separating_crease(
                clean_pattern(annulus_pattern({{{50, 0}, {50, 30.5}}, {{50, 50}, {50, 80}}}))),
            -1);
  EXPECT_EQ(first_non_separating_crease(
                clean_pattern(test::rectangle_pattern(100, 100, {{{50, 0}, {50, 100}}}))),
            -1);
}

}  // namespace
}  // namespace sdog

namespace sdog {
namespace {

TEST(PatternCleaning, PiecesShorterThanTheMergeToleranceJoinIntoOneCrease) {
  // A wave drawn as 200 pieces of 0.5 units, as exporters write curves (L = 100: merging ends
  // reaches 1 unit, two pieces' length).
  std::vector<Polyline2> pieces;
  auto wave = [](double x) { return V2(x, 50 + 5 * std::sin(x / 10)); };
  for (int i = 0; i < 200; ++i) pieces.push_back({wave(0.5 * i), wave(0.5 * (i + 1))});
  const CleanPattern c = clean_pattern(rectangle_pattern(100, 100, pieces));
  ASSERT_EQ(c.creases.size(), 1u);
  EXPECT_EQ(c.creases[0].points.size(), 201u);
  EXPECT_EQ(c.creases[0].points.front(), wave(0));
  EXPECT_EQ(c.creases[0].points.back(), wave(100));
}

TEST(PatternCleaning, BoundaryEndsAHairApartInXShareOneGridLine) {
  // A hexagon whose two left vertices carry crease ends d units apart in x (L = 100): each would
  // pin its own grid line a hair from the other's. Up to L/400 apart they align.
  for (const double d : {0.04, 0.2}) {
    SCOPED_TRACE(d);
    CreasePattern p = rectangle_pattern(100, 100, {{{15, 25}, {85, 25}}, {{15 + d, 75}, {85, 75}}});
    p.sheet.outer = {{0, 50},   {15, 25},  {30, 0},   {70, 0},
                     {100, 50}, {70, 100}, {30, 100}, {15 + d, 75}};
    const CleanPattern c = clean_pattern(p);
    ASSERT_EQ(c.creases.size(), 2u);
    const V2 a = c.creases[0].points.front(), b = c.creases[1].points.front();
    EXPECT_EQ(a.x(), b.x());
    EXPECT_NEAR(a.x(), 15 + d / 2, 1e-12);
    for (const V2& q : {a, b})
      EXPECT_NE(std::find(c.sheet.outer.begin(), c.sheet.outer.end(), q), c.sheet.outer.end())
          << "the boundary vertex moved with the crease end";
    EXPECT_EQ(c.creases[0].points.back(), V2(85, 25)) << "ends far apart stay where drawn";
  }
}

TEST(PatternCleaning, EndsAHairFromABoundaryVertexMoveOntoIt) {
  CreasePattern p = rectangle_pattern(100, 100, {{{15.01, 24.99}, {85, 25}}});
  p.sheet.outer = {{0, 50}, {15, 25}, {30, 0}, {70, 0}, {100, 50}, {70, 100}, {30, 100}};
  const CleanPattern c = clean_pattern(p);
  ASSERT_EQ(c.creases.size(), 1u);
  EXPECT_EQ(c.creases[0].points.front(), V2(15, 25));
}

}  // namespace
}  // namespace sdog

namespace sdog {
namespace {

bool warned(const CleanPattern& c, const std::string& text) {
  return std::any_of(c.warnings.begin(), c.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

TEST(PatternCleaning, ACreaseDrawnTwiceWithASmallOffsetIsMergedWithAWarning) {
  // L = 100: the second drawing's ends lie 0.3 units from the first's, within merging.
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{10, 0}, {10, 100}}, {{10.3, 0}, {10.3, 100}}}));
  ASSERT_EQ(c.creases.size(), 1u);
  EXPECT_TRUE(warned(c, "crease 1 (test crease 1) is drawn again along crease 0 (test crease 0)"));
}

TEST(PatternCleaning, APartDrawnBackOverItselfIsRemovedWithAWarning) {
  const CleanPattern c =
      clean_pattern(rectangle_pattern(100, 100, {{{0, 50}, {100, 50}, {0, 50.0000001}}}));
  ASSERT_EQ(c.creases.size(), 1u);
  EXPECT_EQ(c.creases[0].points.size(), 2u);
  EXPECT_TRUE(warned(c, "runs back over itself"));
}

TEST(PatternCleaning, ADenseFanOfEndsStaysAsDrawn) {
  // Four creases start 0.8 units apart on the bottom edge (L = 100: merging reaches 1 unit, but the
  // group spreads over 2.4): a fan, not one point drawn four times.
  const CleanPattern c = clean_pattern(rectangle_pattern(100, 100,
                                                         {{{50, 0}, {10, 100}},
                                                          {{50.8, 0}, {30, 100}},
                                                          {{51.6, 0}, {50, 100}},
                                                          {{52.4, 0}, {70, 100}}}));
  ASSERT_EQ(c.creases.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(c.creases[k].points.front(), V2(50 + 0.8 * k, 0)) << k;
  EXPECT_TRUE(c.junctions.empty());
}

}  // namespace
}  // namespace sdog

namespace sdog {
namespace {

// Four creases crossing within 5 units at angles down to 4 degrees (L = 100): merging at L/100
// makes one junction of four crossings, through which the two shallow creases then run along each
// other from their own crossing 4 units away.
CreasePattern crowded_crossings() {
  return rectangle_pattern(
      100, 100,
      {{{50, 0}, {50, 100}}, {{0, 20}, {100, 80}}, {{0, 52}, {100, 49}}, {{0, 55}, {100, 45.5}}});
}

TEST(PatternCleaning, CrowdedCrossingsCleanWithFinerTolerancesAndSaySo) {
  const CleanPattern c = clean_pattern(crowded_crossings());
  EXPECT_EQ(c.creases.size(), 4u);
  EXPECT_EQ(c.junctions.size(), 6u) << "every pair of creases crosses once";
  EXPECT_TRUE(warned(c, "denser than cleaning with --merge-tol 0.01 and --snap-tol 0.02 allows"));
  EXPECT_TRUE(warned(c, "no junction could be placed"));
  EXPECT_TRUE(warned(c, "cleaned with --merge-tol 0.001 --snap-tol 0.002"));
}

TEST(PatternCleaning, ChosenTolerancesDoNotAdapt) {
  CleaningOptions chosen;
  chosen.adapt = false;
  try {
    clean_pattern(crowded_crossings(), chosen);
    FAIL() << "cleaned";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no junction could be placed"), std::string::npos)
        << e.what();
  }
}

// A 100 x 100 sheet with the outline `outer` and the creases given as points and assignment.
CreasePattern sheet_with_creases(const Polyline2& outer,
                                 const std::vector<std::pair<Polyline2, Fold>>& creases) {
  CreasePattern p;
  p.source = "test";
  p.sheet.outer = outer;
  p.sheet.bbox = {0, 0, 100, 100};
  for (const auto& [points, fold] : creases) {
    Crease c;
    c.points = points;
    c.fold = fold;
    c.origin = "test crease " + std::to_string(p.creases.size());
    p.creases.push_back(c);
  }
  return p;
}

// The width of the fine grid's narrowest column (mesh units).
double narrowest_column(const DogModel& model) {
  double narrowest = INFINITY;
  for (size_t i = 1; i < model.fine.xs.size(); ++i)
    narrowest = std::min(narrowest, model.fine.xs[i] - model.fine.xs[i - 1]);
  return narrowest;
}

// A 100-unit sheet with a V-shaped bottom edge ((0, 20), (50, 0), (100, 20)). Two creases end on
// its slanted left half at x = 47.1 and 49 (boundary points off the bounding box: fixed grid
// lines), and two pairs of creases meet at (50, 60) and at (tip, 80), each pair a mountain and a
// valley (fold tips). The four x coordinates chain within snap_tol (L/50 = 2), a group with two
// fixed values, which alignment leaves as it is.
CreasePattern hair_pattern(double tip) {
  return sheet_with_creases({{0, 20}, {50, 0}, {100, 20}, {100, 100}, {0, 100}},
                            {
                                {{{49, 0.4}, {0, 40}}, Fold::kMountain},
                                {{{47.1, 1.16}, {0, 30}}, Fold::kMountain},
                                {{{0, 60}, {50, 60}}, Fold::kValley},
                                {{{100, 65}, {50, 60}}, Fold::kMountain},
                                {{{0, 85}, {tip, 80}}, Fold::kMountain},
                                {{{100, 85}, {tip, 80}}, Fold::kValley},
                            });
}

TEST(PatternCleaning, JunctionsAHairApartShareOneGridLineWhereTheirGroupStays) {
  // Without the alignment the tips 5e-6 L apart make a column 1e-4 wide, and the fold scenario
  // diverges at iteration 7; those 0.2% of L apart make columns 0.04 wide.
  for (const double tip : {50.0005, 50.2}) {
    SCOPED_TRACE(tip);
    const CleanPattern c = clean_pattern(hair_pattern(tip));
    ASSERT_EQ(c.junctions.size(), 2u);
    EXPECT_EQ(c.junctions[0].x(), c.junctions[1].x());
    EXPECT_NEAR(c.junctions[0].x(), (50 + tip) / 2, 1e-9) << "the pair's mean";
    const DogModel model = build_dog_model(hair_pattern(tip), {41, 41});
    EXPECT_GT(narrowest_column(model), 0.1)
        << "no grid column a hair wide (mesh units: a column is about 1)";
  }
}

// A 100-unit sheet whose right edge has a jog a hair wide: x = 100 up to y = 10, x = 99.95 above
// (a boundary drawn from pieces whose ends were rounded apart). A valley and a mountain cross the
// sheet and end on the right edge above the jog, at boundary points off the bounding box.
CreasePattern jogged_edge_pattern() {
  return sheet_with_creases({{0, 0}, {100, 0}, {100, 10}, {99.95, 10}, {99.95, 100}, {0, 100}},
                            {
                                {{{0, 40}, {99.95, 50}}, Fold::kValley},
                                {{{0, 70}, {99.95, 80}}, Fold::kMountain},
                            });
}

TEST(PatternCleaning, CreaseEndsAHairFromTheBoundingBoxMoveOntoIt) {
  const CleanPattern c = clean_pattern(jogged_edge_pattern());
  ASSERT_EQ(c.creases.size(), 2u);
  for (const Crease& crease : c.creases) {
    const V2 end = crease.points.front().x() > crease.points.back().x() ? crease.points.front()
                                                                        : crease.points.back();
    EXPECT_EQ(end.x(), 100) << crease.origin << ": onto the outer grid line";
    const auto& outer = c.sheet.outer;
    EXPECT_NE(std::find(outer.begin(), outer.end(), end), outer.end())
        << crease.origin << ": the boundary follows its end";
  }
  const DogModel model = build_dog_model(jogged_edge_pattern(), {41, 41});
  const double narrowest = narrowest_column(model);
  // Without the move the ends pin a grid line 0.02 mesh units from the sheet's outer one.
  EXPECT_GT(narrowest, 0.1) << "no grid column a hair wide (mesh units: a column is about 1)";
}

// A square sheet with a hole whose left edge leans a little, (49.7, 30) to (49.9, 70), clockwise.
// Two creases end on that edge at x = 49.725 and 49.875 (fixed grid lines off the bounding box,
// 30 units apart), and two pairs of creases meet at (50.1, 80) and (50.1005, 90) (fold tips).
// Within L/400 the four x coordinates chain into a group with two fixed values, which stays; the
// tips alone are within L/1000 of each other.
TEST(PatternCleaning, HairPairsInsideARefusedWiderGroupStillAlign) {
  CreasePattern p = sheet_with_creases({{0, 0}, {100, 0}, {100, 100}, {0, 100}},
                                       {
                                           {{{49.725, 35}, {0, 35}}, Fold::kMountain},
                                           {{{49.875, 65}, {0, 65}}, Fold::kValley},
                                           {{{0, 80}, {50.1, 80}}, Fold::kValley},
                                           {{{100, 82}, {50.1, 80}}, Fold::kMountain},
                                           {{{0, 92}, {50.1005, 90}}, Fold::kMountain},
                                           {{{100, 92}, {50.1005, 90}}, Fold::kValley},
                                       });
  p.sheet.holes = {{{49.7, 30}, {60, 30}, {60, 70}, {49.9, 70}}};
  const CleanPattern c = clean_pattern(p);
  ASSERT_EQ(c.junctions.size(), 2u);
  EXPECT_EQ(c.junctions[0].x(), c.junctions[1].x()) << "the tips share one grid line";
  const DogModel model = build_dog_model(p, {41, 41});
  EXPECT_GT(narrowest_column(model), 0.01) << "no grid column a hair wide";
}

// A 100-unit sheet with a V-shaped bottom edge. A mountain runs up x = 49 from the slanted edge
// (a fixed grid line), and two fold tips point at it from the right, at (tip, 62) and
// (tip + gap, 82). Moving a tip onto x = 49 would put it on the mountain.
CreasePattern tips_beside_a_mountain(double tip, double gap = 0.02) {
  return sheet_with_creases({{0, 20}, {50, 0}, {100, 20}, {100, 100}, {0, 100}},
                            {
                                {{{49, 0.4}, {49, 100}}, Fold::kMountain},
                                {{{100, 57}, {tip, 62}}, Fold::kMountain},
                                {{{100, 67}, {tip, 62}}, Fold::kValley},
                                {{{100, 77}, {tip + gap, 82}}, Fold::kMountain},
                                {{{100, 87}, {tip + gap, 82}}, Fold::kValley},
                            });
}

// The x of the mountain's end on the slanted edge after cleaning.
double mountain_end_x(const CleanPattern& c) {
  for (const Crease& crease : c.creases)
    for (const V2& q : {crease.points.front(), crease.points.back()})
      if (q.y() < 1) return q.x();
  return NAN;
}

TEST(PatternCleaning, AFixedEndAHairFromJunctionsThatCannotReachItMovesToThem) {
  const CreasePattern p = tips_beside_a_mountain(49.06);
  const CleanPattern c = clean_pattern(p);
  ASSERT_EQ(c.junctions.size(), 2u);
  EXPECT_NEAR(c.junctions[0].x(), 49.07, 1e-9) << "the tips' mean";
  EXPECT_EQ(c.junctions[1].x(), c.junctions[0].x());
  EXPECT_EQ(mountain_end_x(c), c.junctions[0].x()) << "the end on the slanted edge follows";
  // Without the move the tips pin lines 0.004 mesh units apart and 0.01 from the mountain's.
  EXPECT_GT(narrowest_column(build_dog_model(p, {41, 41})), 0.1) << "no grid column a hair wide";
}

TEST(PatternCleaning, JunctionsThatCannotReachTheirGroupsFixedLineAlignAmongThemselves) {
  // The tips' mean, 49.17, is more than L/1000 from the mountain's end: the end stays.
  const CreasePattern p = tips_beside_a_mountain(49.16);
  const CleanPattern c = clean_pattern(p);
  ASSERT_EQ(c.junctions.size(), 2u);
  EXPECT_NEAR(c.junctions[0].x(), 49.17, 1e-9) << "the tips' mean, off the mountain";
  EXPECT_EQ(c.junctions[1].x(), c.junctions[0].x()) << "the tips share one grid line";
  EXPECT_EQ(mountain_end_x(c), 49);
  // Without their own alignment the tips pin lines 0.004 mesh units apart; with it the narrowest
  // column lies between the mountain and the tips, as drawn.
  EXPECT_GT(narrowest_column(build_dog_model(p, {41, 41})), 0.02) << "no grid column a hair wide";
}

TEST(PatternCleaning, JunctionsThatCannotReachTheirGroupsFixedLineAndAreNotAHairApartStay) {
  // The tips, 1.44 apart, are in one group with the mountain (within L/50) but not a hair apart:
  // each keeps its drawn x (aligned to their mean they would move 0.72 each).
  const CleanPattern c = clean_pattern(tips_beside_a_mountain(49.06, 1.44));
  ASSERT_EQ(c.junctions.size(), 2u);
  std::vector<double> xs = {c.junctions[0].x(), c.junctions[1].x()};
  std::sort(xs.begin(), xs.end());
  EXPECT_EQ(xs[0], 49.06);
  EXPECT_EQ(xs[1], 50.5);
}
}  // namespace
}  // namespace sdog
