// How drawn curves are read (fold_conventions.h): attributes over layers over Origami Simulator's
// colours over dashes; facet lines ignored, cut lines joined with the boundary.
#include <gtest/gtest.h>

#include "base/errors.h"
#include "geometry/input/fold_conventions.h"
#include "geometry/input/svg_pattern.h"
#include "geometry/input/svg_reader.h"
#include "geometry/pattern/crease_pattern.h"

namespace sdog {
namespace {

CreasePattern pattern_of(const std::string& body) {
  const std::string svg =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">"
      "<rect x=\"0\" y=\"0\" width=\"100\" height=\"100\" fill=\"none\" stroke=\"#000\"/>" +
      body + "</svg>";
  return crease_pattern_from_svg(parse_svg(svg, "t.svg"));
}

TEST(FoldConventions, OrigamiSimulatorColoursAndOpacity) {
  const CreasePattern p = pattern_of(
      "<line id=\"m\" x1=\"20\" y1=\"0\" x2=\"20\" y2=\"100\" stroke=\"#ff0000\"/>"
      "<line id=\"v\" x1=\"40\" y1=\"0\" x2=\"40\" y2=\"100\" stroke=\"blue\" "
      "stroke-opacity=\"0.5\"/>"
      "<line x1=\"60\" y1=\"0\" x2=\"60\" y2=\"100\" stroke=\"#ff00ff\"/>"
      "<line x1=\"0\" y1=\"0\" x2=\"100\" y2=\"100\" stroke=\"#ffff00\"/>"
      "<line x1=\"80\" y1=\"0\" x2=\"80\" y2=\"100\" stroke=\"#123456\"/>");
  ASSERT_EQ(p.creases.size(), 4u) << "the yellow facet line is not a crease";
  EXPECT_EQ(p.creases[0].fold, Fold::kMountain);
  EXPECT_EQ(p.creases[0].id, "m");
  EXPECT_FALSE(p.creases[0].angle) << "no opacity given: the run's --angle";
  EXPECT_EQ(p.creases[1].fold, Fold::kValley);
  ASSERT_TRUE(p.creases[1].angle);
  EXPECT_DOUBLE_EQ(*p.creases[1].angle, 90);
  EXPECT_EQ(p.creases[2].fold, Fold::kUnassigned);
  EXPECT_EQ(p.creases[3].fold, Fold::kUnassigned);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find("1 facet line"), std::string::npos);
}

TEST(FoldConventions, DashesDashDotMountainDashedValleyAlsoInBlack) {
  const CreasePattern p = pattern_of(
      "<line x1=\"20\" y1=\"0\" x2=\"20\" y2=\"100\" stroke=\"#000\" stroke-dasharray=\"4 2\"/>"
      "<line x1=\"40\" y1=\"0\" x2=\"40\" y2=\"100\" stroke=\"#333\" stroke-dasharray=\"8 2 1 2\"/>"
      "<line x1=\"60\" y1=\"0\" x2=\"60\" y2=\"100\" stroke=\"#ff0000\" stroke-dasharray=\"4 "
      "2\"/>");
  ASSERT_EQ(p.creases.size(), 3u) << "a dashed black line is a crease";
  EXPECT_EQ(p.creases[0].fold, Fold::kValley);
  EXPECT_EQ(p.creases[1].fold, Fold::kMountain);
  EXPECT_EQ(p.creases[2].fold, Fold::kMountain)
      << "Origami Simulator's colour wins over the dashes";
}

TEST(FoldConventions, DataAttributesWinAndGroupsPassThemOn) {
  const CreasePattern p = pattern_of(
      "<line x1=\"20\" y1=\"0\" x2=\"20\" y2=\"100\" stroke=\"#ff0000\" data-fold=\"valley\" "
      "data-angle=\"45\"/>"
      "<g data-fold=\"flat\"><line x1=\"40\" y1=\"0\" x2=\"40\" y2=\"100\" stroke=\"#000\"/></g>"
      "<line x1=\"60\" y1=\"0\" x2=\"60\" y2=\"100\" stroke=\"#0000ff\" data-angle=\"30\"/>");
  ASSERT_EQ(p.creases.size(), 3u);
  EXPECT_EQ(p.creases[0].fold, Fold::kValley);
  EXPECT_DOUBLE_EQ(*p.creases[0].angle, 45);
  EXPECT_EQ(p.creases[1].fold, Fold::kFlat) << "data-fold makes even a black line a crease";
  EXPECT_EQ(p.creases[2].fold, Fold::kValley);
  EXPECT_DOUBLE_EQ(*p.creases[2].angle, 30);
}

TEST(FoldConventions, BadAttributesAndCutLinesAreClearErrors) {
  auto message = [](const std::string& body) {
    try {
      pattern_of(body);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("<line id=\"c\" x1=\"20\" y1=\"0\" x2=\"20\" y2=\"100\" stroke=\"red\" "
                    "data-fold=\"hill\"/>")
                .find("t.svg:1: <line id=\"c\">: data-fold=\"hill\""),
            std::string::npos);
  EXPECT_NE(
      message("<line x1=\"20\" y1=\"0\" x2=\"20\" y2=\"100\" stroke=\"red\" data-angle=\"-20\"/>")
          .find("0 to 180"),
      std::string::npos);
}

// A sheet outlined by a cut line with a tab, a slit from its edge and one inside it, as
// datasets/slits_and_tab.svg draws them (y down).
TEST(FoldConventions, OpenCutLinesAreSlitsAndAClosedOneWithATabIsTheSheet) {
  const CreasePattern p = crease_pattern_from_svg(
      parse_svg("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-5 -5 110 125\">"
                "<g id=\"CutLine\" fill=\"none\" stroke=\"#000000\">"
                "<path d=\"M 0,0 H 100 V 100 H 60 V 112 H 40 V 100 H 0 Z\"/>"
                "<line id=\"edge-slit\" x1=\"75\" y1=\"100\" x2=\"75\" y2=\"62\"/>"
                "<line id=\"inner-slit\" x1=\"22\" y1=\"25\" x2=\"48\" y2=\"25\"/></g>"
                "<line x1=\"0\" y1=\"45\" x2=\"100\" y2=\"45\" stroke=\"#0000ff\"/></svg>",
                "t.svg"));
  EXPECT_EQ(p.sheet.outer.size(), 8u) << "the square and its tab";
  EXPECT_DOUBLE_EQ(p.sheet.bbox.height(), 112);
  ASSERT_EQ(p.creases.size(), 3u);
  EXPECT_EQ(p.creases[0].kind, CurveKind::kCrease);
  EXPECT_EQ(p.creases[0].fold, Fold::kValley);
  for (size_t k : {1u, 2u}) {
    EXPECT_EQ(p.creases[k].kind, CurveKind::kSlit) << k;
    EXPECT_EQ(p.creases[k].fold, Fold::kFlat) << k;
  }
  EXPECT_EQ(p.creases[1].id, "edge-slit");
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find("2 open boundary or cut line(s) end inside the sheet and are read "
                               "as slits"),
            std::string::npos)
      << p.warnings[0];
  // A cut line alone in a viewBox sheet is a slit too; a black line alone is a boundary left open.
  const CreasePattern lone = pattern_of(
      "<line x1=\"20\" y1=\"0\" x2=\"20\" y2=\"60\" "
      "stroke=\"#00ff00\"/>");
  ASSERT_EQ(lone.creases.size(), 1u);
  EXPECT_EQ(lone.creases[0].kind, CurveKind::kSlit);
}

// A drawing as Illustrator exports one: every stroke black, the meaning in the group ids.
const char* const kIllustratorLayers =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">"
    "<g id=\"Layer_1\">"
    "<g id=\"CutLine\"><polygon points=\"0,0 100,0 100,100 0,100\" fill=\"none\" "
    "stroke=\"#000000\"/></g>"
    "<g id=\"MountainLine\"><line x1=\"30\" y1=\"0\" x2=\"30\" y2=\"100\" fill=\"none\" "
    "stroke=\"#000000\"/></g>"
    "<g id=\"ValleyLine\"><line x1=\"60\" y1=\"0\" x2=\"60\" y2=\"100\" fill=\"none\" "
    "stroke=\"#000000\" stroke-dasharray=\"3,3\"/>"
    "<line x1=\"80\" y1=\"0\" x2=\"80\" y2=\"100\" stroke=\"#ff0000\" stroke-opacity=\"0.5\"/>"
    "</g></g></svg>";

TEST(FoldConventions, IllustratorLayersGiveBlackStrokesTheirMeaning) {
  const CreasePattern p = crease_pattern_from_svg(parse_svg(kIllustratorLayers, "t.svg"));
  EXPECT_DOUBLE_EQ(p.sheet.bbox.width(), 100) << "the cut outline is the sheet";
  ASSERT_EQ(p.creases.size(), 3u);
  EXPECT_EQ(p.creases[0].fold, Fold::kMountain);
  EXPECT_EQ(p.creases[0].layer, "MountainLine");
  EXPECT_EQ(p.creases[1].fold, Fold::kValley);
  EXPECT_EQ(p.creases[1].layer, "ValleyLine");
  EXPECT_EQ(p.creases[2].fold, Fold::kValley) << "the layer wins over the red colour";
  EXPECT_FALSE(p.creases[2].angle) << "the opacity of a mountain colour is not a valley's angle";
}

TEST(FoldConventions, InkscapeLayerLabelsWinOverIdsAndTheNearestGroupDecides) {
  const CreasePattern p = pattern_of(
      "<g inkscape:groupmode=\"layer\" id=\"layer1\" inkscape:label=\"Valley_Fold\" "
      "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\">"
      "<line x1=\"20\" y1=\"0\" x2=\"20\" y2=\"100\" stroke=\"#0000ff\" stroke-opacity=\"0.25\"/>"
      "<g id=\"mountains\"><line x1=\"40\" y1=\"0\" x2=\"40\" y2=\"100\" stroke=\"#333\"/></g>"
      "<g id=\"mountain and valley\"><line x1=\"60\" y1=\"0\" x2=\"60\" y2=\"100\" "
      "stroke=\"#333\"/></g>"
      "<line x1=\"80\" y1=\"0\" x2=\"80\" y2=\"100\" stroke=\"#333\" data-fold=\"flat\"/>"
      "</g>");
  ASSERT_EQ(p.creases.size(), 4u);
  EXPECT_EQ(p.creases[0].fold, Fold::kValley);
  EXPECT_EQ(p.creases[0].layer, "Valley_Fold");
  ASSERT_TRUE(p.creases[0].angle) << "a blue line in a valley layer keeps its opacity angle";
  EXPECT_DOUBLE_EQ(*p.creases[0].angle, 45);
  EXPECT_EQ(p.creases[1].fold, Fold::kMountain) << "the nearest group decides";
  EXPECT_EQ(p.creases[1].layer, "mountains");
  EXPECT_EQ(p.creases[2].fold, Fold::kValley) << "a name with two words says nothing";
  EXPECT_EQ(p.creases[2].layer, "Valley_Fold");
  EXPECT_EQ(p.creases[3].fold, Fold::kFlat) << "data-fold wins over the layer";
  EXPECT_TRUE(p.creases[3].layer.empty());
}

TEST(FoldConventions, ACutLoopInsideTheSheetIsAHoleAndBoundaryLayersOutlineIt) {
  const CreasePattern p = crease_pattern_from_svg(
      parse_svg("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 200 200\">"
                "<g id=\"Outline\"><rect x=\"0\" y=\"0\" width=\"100\" height=\"100\" "
                "stroke=\"#ff0000\" fill=\"none\"/></g>"
                "<circle cx=\"50\" cy=\"50\" r=\"10\" stroke=\"#00ff00\" fill=\"none\"/>"
                "</svg>",
                "t.svg"));
  EXPECT_DOUBLE_EQ(p.sheet.bbox.width(), 100) << "the outline layer, not the viewBox";
  EXPECT_EQ(p.sheet.holes.size(), 1u);
  EXPECT_TRUE(p.creases.empty());
}

TEST(FoldConventions, LayerNamesAreReadInAnyCase) {
  for (const auto& [name, fold] :
       {std::pair{"MOUNTAIN", Fold::kMountain}, std::pair{"valleyLines", Fold::kValley},
        std::pair{"Mountain_Valley", Fold::kUnassigned}}) {
    const std::optional<CurveReading> r = layer_meaning(name);
    if (fold == Fold::kUnassigned) {
      EXPECT_FALSE(r) << name;
      continue;
    }
    ASSERT_TRUE(r) << name;
    EXPECT_EQ(r->fold, fold) << name;
    EXPECT_EQ(r->layer, name);
  }
  EXPECT_EQ(layer_meaning("CutLine")->role, CurveRole::kCut);
  EXPECT_EQ(layer_meaning("boundary")->role, CurveRole::kBoundary);
  EXPECT_FALSE(layer_meaning("Layer_1"));
}

}  // namespace
}  // namespace sdog

namespace sdog {
namespace {

TEST(BoundaryPieces, SeparateSegmentsInAnyOrderAndDirectionAreJoined) {
  // Four black lines, shuffled and two reversed, one with a gap of 0.5 (L/200): one closed sheet.
  const std::string svg =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">"
      "<line x1=\"100\" y1=\"100\" x2=\"100\" y2=\"0\" stroke=\"#000\"/>"
      "<line x1=\"0\" y1=\"0\" x2=\"100\" y2=\"0\" stroke=\"#000\"/>"
      "<line x1=\"0\" y1=\"100\" x2=\"0\" y2=\"0.5\" stroke=\"#000\"/>"
      "<line x1=\"100\" y1=\"100\" x2=\"0\" y2=\"100\" stroke=\"#000\"/>"
      "<line x1=\"50\" y1=\"0\" x2=\"50\" y2=\"100\" stroke=\"#f00\"/>"
      "</svg>";
  const CreasePattern p = crease_pattern_from_svg(parse_svg(svg, "t.svg"));
  EXPECT_TRUE(p.sheet.holes.empty());
  EXPECT_GE(p.sheet.outer.size(), 4u);
  EXPECT_DOUBLE_EQ(p.sheet.bbox.width(), 100);
  EXPECT_DOUBLE_EQ(p.sheet.bbox.height(), 100);
  ASSERT_EQ(p.creases.size(), 1u);
  EXPECT_EQ(p.creases[0].fold, Fold::kMountain);
}

TEST(BoundaryPieces, PiecesThatOverlapByAHairAtTheirJoinsMakeASimpleLoop) {
  // A sheet drawn as short lines, as exporters write it: each piece starts a hair back along the
  // previous one (0.02 units), and two creases start at one of the joins.
  const std::string svg =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">"
      "<line x1=\"0\" y1=\"0\" x2=\"50\" y2=\"0\" stroke=\"#000\"/>"
      "<line x1=\"49.98\" y1=\"0\" x2=\"100\" y2=\"0\" stroke=\"#000\"/>"
      "<line x1=\"100\" y1=\"-0.01\" x2=\"100\" y2=\"100\" stroke=\"#000\"/>"
      "<line x1=\"100.02\" y1=\"100\" x2=\"0\" y2=\"100\" stroke=\"#000\"/>"
      "<line x1=\"0\" y1=\"100.01\" x2=\"0\" y2=\"0.02\" stroke=\"#000\"/>"
      "<line x1=\"50\" y1=\"0\" x2=\"30\" y2=\"100\" stroke=\"#f00\"/>"
      "<line x1=\"50\" y1=\"0\" x2=\"70\" y2=\"100\" stroke=\"#00f\"/>"
      "</svg>";
  const CreasePattern p = crease_pattern_from_svg(parse_svg(svg, "t.svg"));
  EXPECT_TRUE(p.sheet.holes.empty());
  EXPECT_EQ(p.sheet.outer.size(), 5u) << "four corners and the join the creases start from";
  EXPECT_NEAR(p.sheet.bbox.width(), 100, 0.05);
  EXPECT_EQ(p.creases.size(), 2u);
}

// Reading `svg` fails with an InputError whose message contains `text`.
void expect_refused(const std::string& svg, const std::string& text) {
  try {
    crease_pattern_from_svg(parse_svg(svg, "t.svg"));
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(BoundaryPieces, AGapWiderThanTheToleranceIsAnError) {
  const std::string svg =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">"
      "<polyline points=\"0,0 100,0 100,100 0,100 0,5\" fill=\"none\" stroke=\"#000\"/>"
      "</svg>";
  expect_refused(svg, "the sheet boundary (black) is not closed");
}

TEST(BoundaryPieces, LinesThatBranchAreRefusedAtThePointWhereMostMeet) {
  // A square drawn as four black lines and four more from its centre to its corners: three pieces
  // end at each corner, four at the centre.
  const std::string svg =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">"
      "<line x1=\"0\" y1=\"0\" x2=\"100\" y2=\"0\" stroke=\"#000\"/>"
      "<line x1=\"100\" y1=\"0\" x2=\"100\" y2=\"100\" stroke=\"#000\"/>"
      "<line x1=\"100\" y1=\"100\" x2=\"0\" y2=\"100\" stroke=\"#000\"/>"
      "<line x1=\"0\" y1=\"100\" x2=\"0\" y2=\"0\" stroke=\"#000\"/>"
      "<line x1=\"50\" y1=\"50\" x2=\"0\" y2=\"0\" stroke=\"#000\"/>"
      "<line x1=\"50\" y1=\"50\" x2=\"100\" y2=\"0\" stroke=\"#000\"/>"
      "<line x1=\"50\" y1=\"50\" x2=\"100\" y2=\"100\" stroke=\"#000\"/>"
      "<line x1=\"50\" y1=\"50\" x2=\"0\" y2=\"100\" stroke=\"#000\"/>"
      "</svg>";
  expect_refused(svg, "4 sheet boundary (black) or cut lines meet at (50, -50)");
}

}  // namespace
}  // namespace sdog
