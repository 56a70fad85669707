// `sdog run --export fold`: the folded form of every saved state as a FOLD file, read back: valid
// field rules, creases joined (every crease edge between two triangles), and each crease edge of
// the folded state M or V as the drawing assigns the crease it lies on, with the angle reached.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "tests/app/run_sdog.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

using nlohmann::json;

json read_json(const std::string& path) {
  return json::parse(test::slurp(path));
}

// Distance from p to segment [a, b].
double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + t * d - p).norm();
}

TEST(FoldExport, EveryStateIsAFoldedFormWhoseCreasesFoldAsDrawn) {
  const std::string dir = test::temp_dir("fold_export") + "/out";
  const auto r = test::run_sdog("run '" + test::dataset("curved_pleats.svg") +
                                "' --res 21x21 --scenario fold --iters 15 --hold 5 -q "
                                "--frames-every 10 --export fold --out " +
                                dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"surface.fold", "surface_0000.fold", "surface_0010.fold"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name)) << name;
  const json flat = read_json(dir + "/surface_0000.fold");
  const json folded = read_json(dir + "/surface.fold");
  EXPECT_EQ(folded.at("file_spec"), 1.2);
  EXPECT_EQ(folded.at("frame_classes"), json::array({"foldedForm"}));
  const auto& coords = folded.at("vertices_coords");
  const auto& faces = folded.at("faces_vertices");
  const auto& edges = folded.at("edges_vertices");
  const auto& letters = folded.at("edges_assignment");
  const auto& angles = folded.at("edges_foldAngle");
  ASSERT_EQ(letters.size(), edges.size());
  ASSERT_EQ(angles.size(), edges.size());
  ASSERT_EQ(coords.size(), flat.at("vertices_coords").size()) << "the same vertices in every state";
  for (const auto& v : coords) {
    ASSERT_EQ(v.size(), 3u);
    for (const auto& x : v) EXPECT_TRUE(std::isfinite(x.get<double>()));
  }
  // Faces per edge, from the triangles.
  std::map<std::pair<int, int>, int> face_count;
  for (const auto& f : faces) {
    ASSERT_EQ(f.size(), 3u);
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      ASSERT_NE(a, b);
      ASSERT_TRUE(a >= 0 && a < static_cast<int>(coords.size()));
      ++face_count[{std::min(a, b), std::max(a, b)}];
    }
  }
  ASSERT_EQ(face_count.size(), edges.size()) << "every triangle edge once";
  // The drawing's creases, in flat sheet coordinates (pattern.fold's y points down).
  const json pattern = read_json(dir + "/pattern.fold");
  struct Segment {
    Eigen::Vector2d a, b;
    std::string letter;
  };
  std::vector<Segment> creases;
  for (size_t e = 0; e < pattern["edges_vertices"].size(); ++e) {
    const std::string letter = pattern["edges_assignment"][e];
    if (letter != "M" && letter != "V") continue;
    auto point = [&](int k) {
      const auto& c = pattern["vertices_coords"][pattern["edges_vertices"][e][k].get<int>()];
      return Eigen::Vector2d(c[0].get<double>(), -c[1].get<double>());
    };
    creases.push_back({point(0), point(1), letter});
  }
  const auto& flat_coords = flat.at("vertices_coords");
  int mountains = 0, valleys = 0;
  for (size_t e = 0; e < edges.size(); ++e) {
    const int a = edges[e][0], b = edges[e][1];
    const std::string letter = letters[e];
    EXPECT_EQ(face_count[std::make_pair(a, b)], letter == "B" ? 1 : 2)
        << "edge " << e << " " << letter;
    if (letter != "M" && letter != "V") continue;
    (letter == "M" ? mountains : valleys)++;
    const double angle = angles[e];
    EXPECT_GT(std::abs(angle), 45) << "edge " << e;
    EXPECT_EQ(angle < 0, letter == "M") << "FOLD's sign, edge " << e;
    // The drawn crease nearest the edge's middle in the flat state has its letter.
    const Eigen::Vector2d mid(
        0.5 * (flat_coords[a][0].get<double>() + flat_coords[b][0].get<double>()),
        0.5 * (flat_coords[a][1].get<double>() + flat_coords[b][1].get<double>()));
    const Segment* nearest = nullptr;
    double best = INFINITY;
    for (const Segment& s : creases)
      if (const double d = segment_distance(mid, s.a, s.b); d < best) best = d, nearest = &s;
    ASSERT_NE(nearest, nullptr);
    EXPECT_EQ(nearest->letter, letter) << "edge " << e;
  }
  EXPECT_GT(mountains, 20);
  EXPECT_GT(valleys, 20);
  for (const auto& l : flat.at("edges_assignment"))
    EXPECT_NE(l, "M") << "the flat state folds nothing";
}

}  // namespace
}  // namespace sdog
