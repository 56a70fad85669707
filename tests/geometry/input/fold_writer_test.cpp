// The pattern as read, written as FOLD (fold_writer.h): it keeps FOLD's field rules, and the
// project's own reader reads it back into the same sheet, creases and patches.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <tuple>

#include "geometry/input/fold_reader.h"
#include "geometry/input/fold_writer.h"
#include "geometry/input/pattern_file.h"
#include "geometry/input/svg_pattern.h"
#include "geometry/mesh/dog_model.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

// FOLD 1.2's rules for the fields the writer uses: every vertex two finite coordinates, every edge
// two different vertices that exist, one assignment letter of B M V F U C J and one fold angle
// (a number from -180 to 180, or null) per edge, zero on B, F, C and J edges and of the sign of M
// (-) and V (+) edges; no edge twice; a frame class the spec knows; the frame attributes "cuts" and
// "joins" exactly when there are C and J edges (else "noCuts", "noJoins").
void expect_valid_fold(const nlohmann::json& j, const std::string& what) {
  EXPECT_EQ(j.at("file_spec").get<double>(), 1.2) << what;
  EXPECT_TRUE(j.at("file_creator").is_string()) << what;
  for (const auto& c : j.at("frame_classes"))
    EXPECT_TRUE(c == "creasePattern" || c == "foldedForm" || c == "graph") << what;
  const auto& coords = j.at("vertices_coords");
  const auto& edges = j.at("edges_vertices");
  const auto& assignment = j.at("edges_assignment");
  const auto& angle = j.at("edges_foldAngle");
  ASSERT_EQ(assignment.size(), edges.size()) << what;
  ASSERT_EQ(angle.size(), edges.size()) << what;
  for (const auto& v : coords) {
    ASSERT_EQ(v.size(), 2u) << what;
    for (const auto& x : v) EXPECT_TRUE(x.is_number() && std::isfinite(x.get<double>())) << what;
  }
  std::set<std::string> attributes, letters;
  for (const auto& a : j.at("frame_attributes")) attributes.insert(a.get<std::string>());
  for (const auto& a : assignment) letters.insert(a.get<std::string>());
  EXPECT_TRUE(attributes.count("2D")) << what;
  EXPECT_TRUE(attributes.count(letters.count("C") ? "cuts" : "noCuts")) << what;
  EXPECT_TRUE(attributes.count(letters.count("J") ? "joins" : "noJoins")) << what;
  std::set<std::pair<int, int>> seen;
  for (size_t e = 0; e < edges.size(); ++e) {
    ASSERT_EQ(edges[e].size(), 2u) << what;
    const int u = edges[e][0], v = edges[e][1];
    EXPECT_TRUE(u >= 0 && v >= 0 && u < static_cast<int>(coords.size()) &&
                v < static_cast<int>(coords.size()) && u != v)
        << what << ": edge " << e;
    EXPECT_TRUE(seen.insert({std::min(u, v), std::max(u, v)}).second) << what << ": edge " << e;
    const std::string a = assignment[e];
    EXPECT_NE(std::string("BMVFUCJ").find(a), std::string::npos) << what << ": edge " << e;
    if (angle[e].is_null()) continue;
    const double deg = angle[e];
    EXPECT_TRUE(deg >= -180 && deg <= 180) << what << ": edge " << e;
    if (a == "B" || a == "F" || a == "C" || a == "J") EXPECT_EQ(deg, 0) << what << ": edge " << e;
    if (a == "M") EXPECT_LE(deg, 0) << what << ": edge " << e;
    if (a == "V") EXPECT_GE(deg, 0) << what << ": edge " << e;
  }
}

// The creases' segments, each with its assignment, angle and kind, in both directions.
using Segment = std::tuple<double, double, double, double, Fold, double, CurveKind>;
std::set<Segment> crease_segments(const CleanPattern& p) {
  std::set<Segment> out;
  for (const auto& c : p.creases) {
    const size_t n = c.points.size();
    for (size_t i = 0; i + 1 < n + (c.closed ? 1 : 0); ++i) {
      const Eigen::Vector2d &a = c.points[i], &b = c.points[(i + 1) % n];
      const double angle = c.angle.value_or(-1);
      out.insert({a.x(), a.y(), b.x(), b.y(), c.fold, angle, c.kind});
      out.insert({b.x(), b.y(), a.x(), a.y(), c.fold, angle, c.kind});
    }
  }
  return out;
}

// Read back, the pattern has the same sheet, crease segments and patches (a crease through a
// junction may come back as two, which changes nothing).
void expect_same_model(const DogModel& a, const DogModel& b, const std::string& what) {
  EXPECT_EQ(b.clean.sheet.holes.size(), a.clean.sheet.holes.size()) << what;
  EXPECT_EQ(b.clean.sheet.outer, a.clean.sheet.outer) << what;
  EXPECT_TRUE(crease_segments(b.clean) == crease_segments(a.clean)) << what;
  ASSERT_EQ(b.fine.V.rows(), a.fine.V.rows()) << what;
  EXPECT_TRUE(b.fine.V == a.fine.V) << what;
  EXPECT_TRUE(b.fine.F == a.fine.F) << what;
  EXPECT_EQ(b.fine.vertex_patch, a.fine.vertex_patch) << what;
  EXPECT_EQ(b.fine.stitching.points.size(), a.fine.stitching.points.size()) << what;
}

TEST(FoldWriter, EveryDatasetReadsBackIntoTheSamePatches) {
  for (const std::string& file : test::all_datasets()) {
    const DogModel model = build_dog_model(read_crease_pattern(file), {41, 41});
    const std::string text = fold_text(model.clean);
    expect_valid_fold(nlohmann::json::parse(text), file);
    expect_same_model(model, build_dog_model(parse_fold(text, "back.fold"), {41, 41}), file);
  }
}

TEST(FoldWriter, LayersHolesAndCutOutlinesAsTheyWereUnderstood) {
  // Illustrator-style layers, a cut outline with a hole cut out, a valley at 45 degrees.
  const std::string svg =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">"
      "<g id=\"CutLine\"><rect x=\"0\" y=\"0\" width=\"100\" height=\"100\" fill=\"none\" "
      "stroke=\"#000\"/><circle cx=\"20\" cy=\"80\" r=\"8\" fill=\"none\" stroke=\"#000\"/></g>"
      "<g id=\"MountainLine\"><path d=\"M 40 0 Q 60 50 40 100\" fill=\"none\" stroke=\"#000\"/></g>"
      "<g id=\"ValleyLine\"><line x1=\"0\" y1=\"30\" x2=\"100\" y2=\"40\" stroke=\"#000\" "
      "data-angle=\"45\"/></g></svg>";
  const DogModel model =
      build_dog_model(crease_pattern_from_svg(parse_svg(svg, "t.svg")), {41, 41});
  const std::string text = fold_text(model.clean);
  const nlohmann::json j = nlohmann::json::parse(text);
  expect_valid_fold(j, "layers");
  std::multiset<std::string> letters;
  for (const auto& a : j.at("edges_assignment")) letters.insert(a.get<std::string>());
  EXPECT_GT(letters.count("B"), 4u) << "the outline and the hole";
  EXPECT_GT(letters.count("M"), 2u) << "the curved mountain";
  EXPECT_EQ(letters.count("V"), 2u) << "the valley, split at the junction";
  for (size_t e = 0; e < j["edges_assignment"].size(); ++e)
    if (j["edges_assignment"][e] == "V") EXPECT_EQ(j["edges_foldAngle"][e], 45.0);
  expect_same_model(model, build_dog_model(parse_fold(text, "back.fold"), {41, 41}), "layers");
}

}  // namespace
}  // namespace sdog
