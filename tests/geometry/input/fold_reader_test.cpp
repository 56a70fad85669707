// Tests of the FOLD reader (geometry/input/fold_reader.h): the sheet from the B edges, creases from
// the M, V, F and U edges (straight runs of edges joined), fold angles, the y axis (the same
// pattern as SVG and as FOLD gives the same creases) and the errors, each naming the key and index.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "base/errors.h"
#include "geometry/input/fold_reader.h"
#include "geometry/input/pattern_file.h"
#include "geometry/input/svg_pattern.h"
#include "geometry/input/svg_reader.h"
#include "geometry/pattern/crease_pattern.h"
#include "geometry/pattern/pattern_cleaning.h"
#include "geometry/pattern/plane_geometry.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

using nlohmann::json;
using Vec = Eigen::Vector2d;

// A 100 x 100 sheet (file coordinates, y down as in SVG) with its outline split where two
// vertical creases meet it: a valley at x = 30 (edge 8, 90 degrees) and a mountain at x = 70
// (edge 9, -60 degrees).
json square() {
  return {{"file_spec", 1.1},
          {"frame_classes", json::array({"creasePattern"})},
          {"vertices_coords",
           {{0, 0}, {30, 0}, {70, 0}, {100, 0}, {100, 100}, {70, 100}, {30, 100}, {0, 100}}},
          {"edges_vertices",
           {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 0}, {1, 6}, {2, 5}}},
          {"edges_assignment", {"B", "B", "B", "B", "B", "B", "B", "B", "V", "M"}},
          {"edges_foldAngle", {0, 0, 0, 0, 0, 0, 0, 0, 90, -60}}};
}

CreasePattern read(const json& fold) {
  return parse_fold(fold.dump(), "t.fold");
}

// Adds a vertex; returns its index.
int add_vertex(json& fold, double x, double y) {
  fold["vertices_coords"].push_back(json::array({x, y}));
  return static_cast<int>(fold["vertices_coords"].size()) - 1;
}

void add_edge(json& fold, int u, int v, const std::string& assignment, json angle) {
  fold["edges_vertices"].push_back(json::array({u, v}));
  fold["edges_assignment"].push_back(assignment);
  fold["edges_foldAngle"].push_back(std::move(angle));
}

// The message of the InputError that `read` throws.
template <class Read>
std::string message_of(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
std::string error_of_text(const std::string& text) {
  return message_of([&] { parse_fold(text, "t.fold"); });
}
std::string error_of(const json& fold) {
  return error_of_text(fold.dump());
}

#define EXPECT_HAS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

TEST(FoldReader, ReadsTheSheetTheCreasesTheirAssignmentsAndAngles) {
  const CreasePattern p = read(square());
  EXPECT_EQ(p.source, "t.fold");
  ASSERT_EQ(p.sheet.outer.size(), 8u);
  EXPECT_GT(signed_area(p.sheet.outer), 0) << "the outer boundary is counter-clockwise";
  EXPECT_NEAR(signed_area(p.sheet.outer), 10000, 1e-9);
  EXPECT_TRUE(p.sheet.holes.empty());
  EXPECT_FALSE(p.sheet.from_viewbox);
  EXPECT_EQ(p.sheet.bbox.xmin, 0);
  EXPECT_EQ(p.sheet.bbox.xmax, 100);
  EXPECT_EQ(p.sheet.bbox.ymin, -100) << "FOLD's y is negated, as SVG's";
  EXPECT_EQ(p.sheet.bbox.ymax, 0);
  ASSERT_EQ(p.creases.size(), 2u);
  const Crease& valley = p.creases[0];
  EXPECT_EQ(valley.fold, Fold::kValley);
  ASSERT_TRUE(valley.angle.has_value());
  EXPECT_EQ(*valley.angle, 90);
  EXPECT_EQ(valley.id, "edge 8");
  EXPECT_EQ(valley.origin, "t.fold: edge 8");
  EXPECT_FALSE(valley.closed);
  EXPECT_EQ(valley.points, (Polyline2{Vec(30, 0), Vec(30, -100)}));
  const Crease& mountain = p.creases[1];
  EXPECT_EQ(mountain.fold, Fold::kMountain);
  ASSERT_TRUE(mountain.angle.has_value());
  EXPECT_EQ(*mountain.angle, 60) << "the angle is a magnitude; the direction is the assignment";
  EXPECT_EQ(mountain.id, "edge 9");
  EXPECT_TRUE(p.warnings.empty());
}

TEST(FoldReader, AnglesAreOptionalAndLowerCaseAssignmentsAreRead) {
  json f = square();
  f.erase("edges_foldAngle");
  f["edges_assignment"] = {"b", "b", "b", "b", "b", "b", "b", "b", "v", "m"};
  const CreasePattern p = read(f);
  ASSERT_EQ(p.creases.size(), 2u);
  EXPECT_EQ(p.creases[0].fold, Fold::kValley);
  EXPECT_FALSE(p.creases[0].angle.has_value());
  EXPECT_EQ(p.creases[1].fold, Fold::kMountain);
  EXPECT_FALSE(p.creases[1].angle.has_value());
}

TEST(FoldReader, FlatAndUnassignedEdgesAndNullAngles) {
  json f = square();
  f["edges_assignment"][8] = "F";
  f["edges_foldAngle"][8] = 0;
  f["edges_assignment"][9] = "U";
  f["edges_foldAngle"][9] = nullptr;  // Origami Simulator writes null where it has no angle
  f["edges_foldAngle"][0] = nullptr;
  CreasePattern p = read(f);
  ASSERT_EQ(p.creases.size(), 2u);
  EXPECT_EQ(p.creases[0].fold, Fold::kFlat);
  EXPECT_EQ(p.creases[0].angle, std::optional<double>(0)) << "as the SVG reader's flat creases";
  EXPECT_EQ(p.creases[1].fold, Fold::kUnassigned);
  EXPECT_FALSE(p.creases[1].angle.has_value());
  // An unassigned edge with a nonzero angle takes the assignment of its sign.
  f["edges_foldAngle"][9] = -45;
  p = read(f);
  EXPECT_EQ(p.creases[1].fold, Fold::kMountain);
  EXPECT_EQ(p.creases[1].angle, std::optional<double>(45));
  f["edges_foldAngle"][9] = 30;
  EXPECT_EQ(read(f).creases[1].fold, Fold::kValley);
  f["edges_foldAngle"][9] = 0;
  p = read(f);
  EXPECT_EQ(p.creases[1].fold, Fold::kUnassigned);
  EXPECT_FALSE(p.creases[1].angle.has_value()) << "0 on an unassigned edge says nothing";
}

TEST(FoldReader, StraightRunsOfEdgesBecomeOneCrease) {
  json f = square();
  // The valley at x = 30 as three edges, listed out of order and in both directions.
  const int a = add_vertex(f, 30, 25), b = add_vertex(f, 30, 60);
  f["edges_vertices"][8] = {1, a};
  add_edge(f, 6, b, "V", 90);
  add_edge(f, b, a, "V", 90);
  const CreasePattern p = read(f);
  ASSERT_EQ(p.creases.size(), 2u);
  EXPECT_EQ(p.creases[0].id, "edge 8") << "named after its lowest-numbered edge";
  EXPECT_EQ(p.creases[0].points,
            (Polyline2{Vec(30, 0), Vec(30, -25), Vec(30, -60), Vec(30, -100)}));
  EXPECT_EQ(p.creases[0].fold, Fold::kValley);
  EXPECT_EQ(p.creases[1].id, "edge 9");
}

TEST(FoldReader, EdgesThatTurnOrDifferInAssignmentOrAngleStaySeparate) {
  json f = square();
  // The valley bends at (40, 50): two creases, which pattern cleaning joins.
  const int bend = add_vertex(f, 40, 50);
  f["edges_vertices"][8] = {1, bend};
  add_edge(f, bend, 6, "V", 90);
  CreasePattern p = read(f);
  ASSERT_EQ(p.creases.size(), 3u);
  EXPECT_EQ(p.creases[0].points, (Polyline2{Vec(30, 0), Vec(40, -50)}));
  EXPECT_EQ(p.creases[2].points, (Polyline2{Vec(40, -50), Vec(30, -100)}));
  EXPECT_EQ(p.creases[2].id, "edge 10");
  EXPECT_EQ(clean_pattern(p).creases.size(), 2u)
      << "cleaning joins the two halves of the bent valley";

  // Straight on, but with another angle or assignment.
  f = square();
  const int mid = add_vertex(f, 30, 50);
  f["edges_vertices"][8] = {1, mid};
  add_edge(f, mid, 6, "V", 45);
  EXPECT_EQ(read(f).creases.size(), 3u) << "another angle";
  f["edges_assignment"][10] = "M";
  f["edges_foldAngle"][10] = -90;
  EXPECT_EQ(read(f).creases.size(), 3u) << "another assignment";
  // A third valley at the vertex: no crease runs through it.
  f["edges_assignment"][10] = "V";
  f["edges_foldAngle"][10] = 90;
  const int side = add_vertex(f, 0, 50);
  add_edge(f, mid, side, "V", 90);
  EXPECT_EQ(read(f).creases.size(), 4u);
}

TEST(FoldReader, ACrossingCreaseOfAnotherClassDoesNotStopAStraightOne) {
  json f = square();
  const int mid = add_vertex(f, 30, 50), left = add_vertex(f, 0, 50), right = add_vertex(f, 70, 50);
  f["edges_vertices"][8] = {1, mid};
  add_edge(f, mid, 6, "V", 90);
  add_edge(f, left, mid, "M", -30);
  add_edge(f, mid, right, "M", -30);
  const CreasePattern p = read(f);
  ASSERT_EQ(p.creases.size(), 3u);
  EXPECT_EQ(p.creases[0].points, (Polyline2{Vec(30, 0), Vec(30, -50), Vec(30, -100)}));
  EXPECT_EQ(p.creases[2].points, (Polyline2{Vec(0, -50), Vec(30, -50), Vec(70, -50)}));
  EXPECT_EQ(p.creases[2].fold, Fold::kMountain);
}

TEST(FoldReader, ASecondBoundaryLoopIsAHole) {
  json f = square();
  // The hole comes first and counter-clockwise on the page; the larger loop is still the outer one.
  json g = f;
  g["vertices_coords"] = json::array();
  g["edges_vertices"] = json::array();
  g["edges_assignment"] = json::array();
  g["edges_foldAngle"] = json::array();
  const int h0 = add_vertex(g, 40, 40), h1 = add_vertex(g, 40, 60), h2 = add_vertex(g, 60, 60),
            h3 = add_vertex(g, 60, 40);
  for (const auto& [u, v] :
       std::vector<std::pair<int, int>>{{h0, h1}, {h1, h2}, {h2, h3}, {h3, h0}})
    add_edge(g, u, v, "B", nullptr);
  const int offset = 4;
  for (const auto& p : f["vertices_coords"]) g["vertices_coords"].push_back(p);
  for (size_t e = 0; e < f["edges_vertices"].size(); ++e)
    add_edge(g, f["edges_vertices"][e][0].get<int>() + offset,
             f["edges_vertices"][e][1].get<int>() + offset, f["edges_assignment"][e],
             f["edges_foldAngle"][e]);
  const CreasePattern p = read(g);
  EXPECT_EQ(p.sheet.outer.size(), 8u);
  EXPECT_GT(signed_area(p.sheet.outer), 0);
  ASSERT_EQ(p.sheet.holes.size(), 1u);
  EXPECT_LT(signed_area(p.sheet.holes[0]), 0) << "holes are clockwise";
  EXPECT_NEAR(signed_area(p.sheet.holes[0]), -400, 1e-9);
  ASSERT_EQ(p.creases.size(), 2u);
  EXPECT_EQ(p.creases[0].id, "edge 12");
}

TEST(FoldReader, RepeatedEdgesAreDroppedWithAWarningAndJoinEdgesIgnored) {
  json f = square();
  add_edge(f, 6, 1, "V", 90);  // edge 10 repeats edge 8
  add_edge(f, 0, 2, "J", nullptr);
  const CreasePattern p = read(f);
  EXPECT_EQ(p.creases.size(), 2u);
  ASSERT_EQ(p.warnings.size(), 2u);
  EXPECT_HAS(p.warnings[0],
             "t.fold: edge 10 (V) joins the same vertices (6 and 1) as edge 8 (V); ignored");
  EXPECT_HAS(p.warnings[1], "1 join edge(s)");
}

TEST(FoldReader, OnlyTheTopLevelFrameIsRead) {
  json f = square();
  json other = square();
  other["edges_assignment"][8] = "M";
  other["edges_foldAngle"][8] = -10;
  f["file_frames"] = json::array({other});
  EXPECT_EQ(read(f).creases[0].fold, Fold::kValley);
  const json frames_only = {{"file_frames", json::array({square()})}};
  EXPECT_HAS(error_of(frames_only),
             "t.fold: no vertices_coords (only the top-level frame is read, not file_frames)");
}

TEST(FoldReader, ThreeDimensionalCoordinatesInThePlaneAreRead) {
  json f = square();
  for (auto& c : f["vertices_coords"]) c.push_back(0);
  EXPECT_EQ(read(f).creases[0].points, (Polyline2{Vec(30, 0), Vec(30, -100)}));
  f["vertices_coords"][3][2] = 5;
  EXPECT_HAS(error_of(f), "t.fold: $.vertices_coords[3][2]: coordinate 5 off the plane z = 0");
}

TEST(FoldReader, ReadCreasePatternReadsFoldFilesByTheirExtension) {
  const std::string dir = test::temp_dir("fold_reader");
  const std::string path = test::write_file(dir, "square.FOLD", square().dump(2));
  const CreasePattern p = read_crease_pattern(path);
  EXPECT_EQ(p.source, path);
  ASSERT_EQ(p.creases.size(), 2u);
  EXPECT_EQ(p.creases[1].origin, path + ": edge 9");
  EXPECT_HAS(message_of([&] { read_crease_pattern(dir + "/missing.fold"); }),
             "missing.fold: cannot open file");
}

// The same pattern drawn in SVG (Origami Simulator's colours, opacity as the angle) and written as
// FOLD with the same coordinates reads into the same creases: FOLD's y axis is SVG's.
TEST(FoldReader, APatternAsSvgAndAsFoldGivesTheSameCreases) {
  const std::string svg =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 80\">\n"
      "  <polygon points=\"0,0 100,0 100,80 0,80\" fill=\"none\" stroke=\"#000000\"/>\n"
      "  <line x1=\"20\" y1=\"0\" x2=\"45\" y2=\"80\" stroke=\"#ff0000\" opacity=\"0.5\"/>\n"
      "  <polyline points=\"60,0 70,40 90,80\" fill=\"none\" stroke=\"#0000ff\"/>\n"
      "</svg>\n";
  const CreasePattern from_svg = crease_pattern_from_svg(parse_svg(svg, "t.svg"));
  const json fold = {
      {"vertices_coords",
       {{0, 0}, {100, 0}, {100, 80}, {0, 80}, {20, 0}, {45, 80}, {60, 0}, {70, 40}, {90, 80}}},
      {"edges_vertices", {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {6, 7}, {7, 8}}},
      {"edges_assignment", {"B", "B", "B", "B", "M", "V", "V"}},
      {"edges_foldAngle", {0, 0, 0, 0, -90, nullptr, nullptr}}};
  const CreasePattern from_fold = read(fold);
  EXPECT_EQ(from_fold.sheet.bbox.xmin, from_svg.sheet.bbox.xmin);
  EXPECT_EQ(from_fold.sheet.bbox.ymin, from_svg.sheet.bbox.ymin);
  EXPECT_EQ(from_fold.sheet.bbox.xmax, from_svg.sheet.bbox.xmax);
  EXPECT_EQ(from_fold.sheet.bbox.ymax, from_svg.sheet.bbox.ymax);
  EXPECT_DOUBLE_EQ(signed_area(from_fold.sheet.outer), signed_area(from_svg.sheet.outer));
  ASSERT_EQ(from_svg.creases.size(), 2u);
  // The bent valley is two FOLD edges: two creases, joined again by cleaning.
  ASSERT_EQ(from_fold.creases.size(), 3u);
  EXPECT_EQ(from_fold.creases[0].points, from_svg.creases[0].points);
  EXPECT_EQ(from_fold.creases[0].fold, Fold::kMountain);
  EXPECT_EQ(from_svg.creases[0].fold, Fold::kMountain);
  EXPECT_EQ(from_fold.creases[0].angle, from_svg.creases[0].angle);
  const CleanPattern clean_svg = clean_pattern(from_svg), clean_fold = clean_pattern(from_fold);
  ASSERT_EQ(clean_fold.creases.size(), clean_svg.creases.size());
  for (size_t k = 0; k < clean_svg.creases.size(); ++k) {
    EXPECT_EQ(clean_fold.creases[k].points, clean_svg.creases[k].points) << "crease " << k;
    EXPECT_EQ(clean_fold.creases[k].fold, clean_svg.creases[k].fold) << "crease " << k;
  }
}

TEST(FoldReaderErrors, TextThatIsNotJson) {
  EXPECT_HAS(error_of_text("{\n  \"vertices_coords\": [[0, 0],\n"),
             "t.fold: not valid JSON (parse error at line 3");
  EXPECT_HAS(error_of_text("[1, 2]"), "t.fold: $: expected a JSON object");
}

TEST(FoldReaderErrors, ACoordinateBeyondTheRangeOfNumbers) {
  std::string text = square().dump();
  text.replace(text.find("[100,0]"), 7, "[1e999,0]");
  EXPECT_HAS(error_of_text(text),
             "t.fold: not valid JSON (number overflow parsing '1e999' at line 1, column ");
  EXPECT_HAS(error_of_text(text), "not a finite number");
}

TEST(FoldReaderErrors, MissingOrWronglyTypedKeys) {
  json f = square();
  f.erase("vertices_coords");
  EXPECT_HAS(error_of(f), "t.fold: no vertices_coords; ");
  f = square();
  f.erase("edges_assignment");
  EXPECT_HAS(error_of(f),
             "t.fold: no edges_assignment; without assignments the sheet boundary (the B edges) is "
             "unknown");
  f = square();
  f["edges_vertices"] = 3;
  EXPECT_HAS(error_of(f), "t.fold: $.edges_vertices: expected an array");
  f = square();
  f["vertices_coords"][2] = json::array({1});
  EXPECT_HAS(error_of(f), "t.fold: $.vertices_coords[2]: expected [x, y]");
  f = square();
  f["vertices_coords"][2][1] = "7";
  EXPECT_HAS(error_of(f), "t.fold: $.vertices_coords[2][1]: expected a number");
  f = square();
  f["edges_vertices"][4] = json::array({4});
  EXPECT_HAS(error_of(f), "t.fold: $.edges_vertices[4]: expected [u, v]");
  f = square();
  f["edges_vertices"][4][0] = 1.5;
  EXPECT_HAS(error_of(f), "t.fold: $.edges_vertices[4][0]: expected an integer");
  f = square();
  f["edges_assignment"][3] = 66;
  EXPECT_HAS(error_of(f), "t.fold: $.edges_assignment[3]: expected a string");
  f = square();
  f["edges_foldAngle"][9] = "-60";
  EXPECT_HAS(error_of(f), "t.fold: $.edges_foldAngle[9]: expected a number");
  f = square();
  f["frame_classes"] = "creasePattern";
  EXPECT_HAS(error_of(f), "t.fold: $.frame_classes: expected an array");
}

TEST(FoldReaderErrors, VertexIndicesOutOfRangeOrRepeated) {
  json f = square();
  f["edges_vertices"][3] = {3, 12};
  EXPECT_HAS(error_of(f),
             "t.fold: $.edges_vertices[3][1]: vertex 12 does not exist (vertices_coords has 8 "
             "vertices, numbered from 0)");
  f["edges_vertices"][3] = {-1, 4};
  EXPECT_HAS(error_of(f), "t.fold: $.edges_vertices[3][0]: expected an integer >= 0, got -1");
  f["edges_vertices"][3] = {2, 2};
  EXPECT_HAS(error_of(f), "t.fold: $.edges_vertices[3]: the edge joins vertex 2 to itself");
  f = square();
  f["vertices_coords"].push_back(json::array({100, 0}));
  f["edges_vertices"][3] = {3, 8};
  EXPECT_HAS(error_of(f),
             "t.fold: $.edges_vertices[3]: the edge has zero length (vertices 3 and 8 are both at "
             "[100, 0])");
}

TEST(FoldReaderErrors, ArraysOfAnotherLengthThanTheEdges) {
  json f = square();
  f["edges_assignment"].erase(9);
  EXPECT_HAS(error_of(f),
             "t.fold: $.edges_assignment: has 9 entries, edges_vertices has 10; there must be one "
             "for each edge");
  f = square();
  f["edges_foldAngle"].push_back(0);
  EXPECT_HAS(error_of(f), "t.fold: $.edges_foldAngle: has 11 entries, edges_vertices has 10");
}

TEST(FoldReaderErrors, AssignmentsThatCannotBeUsed) {
  json f = square();
  f["edges_assignment"][4] = "X";
  EXPECT_HAS(
      error_of(f),
      "t.fold: $.edges_assignment[4]: unknown assignment \"X\"; FOLD's are B, M, V, F, U, C and J");
  f["edges_assignment"][4] = "MV";
  EXPECT_HAS(error_of(f), "t.fold: $.edges_assignment[4]: unknown assignment \"MV\"");
  f["edges_assignment"][4] = "M\nV";
  EXPECT_HAS(error_of(f), "unknown assignment \"M\\nV\"") << "the message stays on one line";
  f = square();
  f["edges_assignment"][9] = "c";
  f["edges_foldAngle"][9] = 10;
  EXPECT_HAS(error_of(f), "t.fold: $.edges_foldAngle[9]: fold angle 10 on a cut (C)");
}

TEST(FoldReader, CutsAreSlitsAndJoinsAreLeftToCleaning) {
  json f = square();
  f["edges_assignment"][9] = "C";
  f["edges_foldAngle"][9] = nullptr;
  const int a = add_vertex(f, 30, 50), b = add_vertex(f, 50, 50);
  add_edge(f, a, b, "J", nullptr);
  const CreasePattern p = read(f);
  ASSERT_EQ(p.creases.size(), 2u) << "the join edge is no curve";
  EXPECT_EQ(p.creases[0].kind, CurveKind::kCrease);
  EXPECT_EQ(p.creases[1].kind, CurveKind::kSlit);
  EXPECT_EQ(p.creases[1].fold, Fold::kFlat);
  EXPECT_FALSE(p.creases[1].angle);
}

TEST(FoldReaderErrors, FoldAnglesOutOfRangeOrAgainstTheAssignment) {
  json f = square();
  f["edges_foldAngle"][8] = 200;
  EXPECT_HAS(error_of(f),
             "t.fold: $.edges_foldAngle[8]: fold angle 200 outside [-180, 180] degrees");
  f["edges_foldAngle"][8] = -90;
  EXPECT_HAS(error_of(f),
             "t.fold: $.edges_foldAngle[8]: fold angle -90 on a valley crease (V); FOLD's valley "
             "angles are positive");
  f = square();
  f["edges_foldAngle"][9] = 60;
  EXPECT_HAS(error_of(f), "t.fold: $.edges_foldAngle[9]: fold angle 60 on a mountain crease (M)");
  f = square();
  f["edges_assignment"][9] = "F";
  EXPECT_HAS(
      error_of(f),
      "t.fold: $.edges_foldAngle[9]: fold angle -60 on a flat crease (F), which does not fold");
  f = square();
  f["edges_foldAngle"][2] = 10;
  EXPECT_HAS(error_of(f), "t.fold: $.edges_foldAngle[2]: fold angle 10 on a boundary edge (B)");
}

TEST(FoldReaderErrors, AFoldedForm) {
  json f = square();
  f["frame_classes"] = json::array({"foldedForm"});
  EXPECT_HAS(error_of(f), "t.fold: $.frame_classes: a folded form, not a crease pattern");
  f["frame_classes"] = json::array({"foldedForm", "creasePattern"});
  EXPECT_EQ(read(f).creases.size(), 2u);
}

TEST(FoldReaderErrors, ABoundaryThatIsMissingOpenOrBranching) {
  json f = square();
  for (int e = 0; e < 8; ++e) f["edges_assignment"][e] = "U";
  EXPECT_HAS(error_of(f),
             "t.fold: no boundary edge (B) in edges_assignment, so the sheet is unknown");
  f = square();
  f["edges_assignment"][5] = "U";  // edge 5 joins vertices 5 and 6
  EXPECT_HAS(error_of(f),
             "t.fold: edge 4: the sheet boundary (B edges) is not closed: it stops at vertex 5 at "
             "[70, 100]");
  f = square();
  add_edge(f, 0, 4, "B", 0);
  EXPECT_HAS(error_of(f), "the sheet boundary branches at vertex 0 at [0, 0], which has 3 B edges");
}

TEST(FoldReaderErrors, ASheetOfZeroArea) {
  const json f = {{"vertices_coords", {{0, 0}, {100, 0}, {50, 1e-12}}},
                  {"edges_vertices", {{0, 1}, {1, 2}, {2, 0}}},
                  {"edges_assignment", {"B", "B", "B"}}};
  EXPECT_HAS(error_of(f), "t.fold: edge 0: the sheet has zero area");
}

}  // namespace
}  // namespace sdog
