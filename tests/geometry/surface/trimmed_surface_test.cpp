// The trimmed surface: patches clipped at their creases and at the sheet's boundary. Areas of
// patterns whose patches are known in closed form, seams that close, and the sheet's area on every
// dataset and reference pattern.
#include "geometry/surface/trimmed_surface.h"
#include "geometry/input/pattern_file.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>

#include "geometry/mesh/dog_model.h"
#include "geometry/pattern/plane_geometry.h"
#include "tests/geometry/pattern_builders.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

using test::rectangle_pattern;

// Area of each patch's triangles.
std::vector<double> patch_areas(const DogMesh& mesh, const TrimmedSurface& s) {
  std::vector<double> areas(mesh.patch_count(), 0.0);
  for (int t = 0; t < s.triangle_count(); ++t) {
    const Eigen::Vector3d a = s.V.row(s.T(t, 0)), b = s.V.row(s.T(t, 1)), c = s.V.row(s.T(t, 2));
    areas[s.vertex_patch[s.T(t, 0)]] += 0.5 * (b - a).cross(c - a).norm();
  }
  return areas;
}

// The area of the cleaned sheet (outer boundary minus holes), in mesh units.
double sheet_area(const DogModel& m) {
  double area = std::abs(signed_area(m.clean.sheet.outer));
  for (const auto& h : m.clean.sheet.holes) area -= std::abs(signed_area(h));
  return area * m.fine.scale * m.fine.scale;
}

// Areas in sheet units (the test patterns are 100 x 100 with 1 / scale = 100 / (n - 1)).
double mesh_area(const DogMesh& mesh, double sheet_units) {
  return sheet_units * mesh.scale * mesh.scale;
}

// The edges used by a single triangle that are not on the sheet's outer rectangle [0, w] x [0, h]
// (at rest: `flat`) must each have a twin with the same end positions in `s` (either direction):
// the patches meet along their creases without a gap. (A twin is another patch's edge, or, where a
// crease passes within rounding of a grid vertex, the other side of a sliver of no area.) Returns
// the number of edges without a twin.
int open_seams(const TrimmedSurface& s, const TrimmedSurface& flat, double w, double h,
               double tol) {
  std::map<std::pair<int, int>, int> uses;
  for (int t = 0; t < s.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = s.T(t, k), b = s.T(t, (k + 1) % 3);
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<int, int>> border;
  for (const auto& [e, n] : uses)
    if (n == 1) border.push_back(e);
  auto on_outer = [&](int v) {
    const Eigen::Vector3d p = flat.V.row(v);
    return std::abs(p.x()) < tol || std::abs(p.y()) < tol || std::abs(p.x() - w) < tol ||
           std::abs(p.y() - h) < tol;
  };
  auto same = [&](int u, int v) { return (s.V.row(u) - s.V.row(v)).norm() < tol; };
  int open = 0;
  for (const auto& [a, b] : border) {
    if (same(a, b))
      continue;  // an edge shorter than tol (a crease point next to a grid vertex) is a point
    const Eigen::Vector3d mid = 0.5 * (flat.V.row(a) + flat.V.row(b)).transpose();
    if (on_outer(a) && on_outer(b) &&
        (std::abs(mid.x()) < tol || std::abs(mid.y()) < tol || std::abs(mid.x() - w) < tol ||
         std::abs(mid.y() - h) < tol))
      continue;
    bool twin = false;
    for (const auto& [c, d] : border)
      if (std::make_pair(c, d) != std::make_pair(a, b) &&
          ((same(a, c) && same(b, d)) || (same(a, d) && same(b, c)))) {
        twin = true;
        break;
      }
    if (!twin) ++open;
  }
  return open;
}

// A smooth non-planar map of the flat sheet: what a folded state does to the copies of a crease
// point (same flat position, same image).
Eigen::MatrixX3d bent(const DogMesh& mesh) {
  Eigen::MatrixX3d X = mesh.V;
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const double x = mesh.V(v, 0), y = mesh.V(v, 1);
    X.row(v) << x + 0.1 * std::sin(y), y, 0.05 * x * x + std::cos(0.3 * y);
  }
  return X;
}

TEST(TrimmedSurface, APlainSheetIsItsQuadsAsTwoTrianglesEach) {
  const DogModel m = build_dog_model(rectangle_pattern(300, 200), {11, 7});
  const TrimmedSurface s = trimmed_surface(m.fine, m.fine.V);
  EXPECT_EQ(s.triangle_count(), 2 * m.fine.quad_count());
  EXPECT_EQ(s.vertex_count(), m.fine.vertex_count());
  EXPECT_NEAR(surface_area(s), mesh_area(m.fine, 300 * 200), 1e-9);
  for (int r = 0; r < s.vertex_count(); ++r) EXPECT_NEAR(s.N(r, 2), 1.0, 1e-12);
}

TEST(TrimmedSurface, ACreaseThroughGridVerticesHalvesTheSheet) {
  for (int n : {5, 9, 21}) {
    const DogModel m = build_dog_model(rectangle_pattern(100, 100, {{{0, 0}, {100, 100}}}), {n, n});
    const TrimmedSurface s = trimmed_surface(m.fine, m.fine.V);
    const auto areas = patch_areas(m.fine, s);
    ASSERT_EQ(areas.size(), 2u);
    for (double a : areas) EXPECT_NEAR(a, mesh_area(m.fine, 5000), 1e-9) << n;
    const double side = m.fine.xs.back();
    EXPECT_EQ(open_seams(s, s, side, side, 1e-9), 0) << n;
  }
}

TEST(TrimmedSurface, ACreaseAlongAGridLineCutsNoCell) {
  const DogModel m = build_dog_model(rectangle_pattern(100, 100, {{{50, 0}, {50, 100}}}), {5, 5});
  EXPECT_TRUE(m.fine.quad_pieces.empty());
  const TrimmedSurface s = trimmed_surface(m.fine, m.fine.V);
  const auto areas = patch_areas(m.fine, s);
  for (double a : areas) EXPECT_NEAR(a, mesh_area(m.fine, 5000), 1e-9);
  EXPECT_EQ(open_seams(s, s, 4, 4, 1e-9), 0);
}

TEST(TrimmedSurface, FourPatchesMeetAtACrossing) {
  const DogModel m = build_dog_model(
      rectangle_pattern(100, 100, {{{0, 61}, {100, 61}}, {{37, 0}, {37, 100}}}), {11, 11});
  const TrimmedSurface s = trimmed_surface(m.fine, m.fine.V);
  std::vector<double> areas = patch_areas(m.fine, s), expected;
  for (double a : {37.0 * 61, 63.0 * 61, 37.0 * 39, 63.0 * 39})
    expected.push_back(mesh_area(m.fine, a));
  std::sort(areas.begin(), areas.end());
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(areas.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(areas[k], expected[k], 1e-9);
}

TEST(TrimmedSurface, ThreeSlantedCreasesMeetAtAJunction) {
  // Three straight creases from (50, 50) cut cells on their way; straight lines snap to themselves,
  // so each patch has its polygon's area.
  const DogModel m = build_dog_model(
      rectangle_pattern(100, 100,
                        {{{0, 20}, {50, 50}}, {{50, 50}, {100, 30}}, {{50, 50}, {70, 100}}}),
      {21, 21});
  ASSERT_EQ(m.fine.patch_count(), 3);
  ASSERT_FALSE(m.fine.stitching.junctions.empty());
  EXPECT_FALSE(m.fine.quad_pieces.empty());
  const TrimmedSurface s = trimmed_surface(m.fine, m.fine.V);
  std::vector<double> areas = patch_areas(m.fine, s), expected;
  for (const Polyline2& p : {Polyline2{{0, 20}, {50, 50}, {70, 100}, {0, 100}},
                             Polyline2{{50, 50}, {100, 30}, {100, 100}, {70, 100}},
                             Polyline2{{0, 0}, {100, 0}, {100, 30}, {50, 50}, {0, 20}}})
    expected.push_back(mesh_area(m.fine, std::abs(signed_area(p))));
  std::sort(areas.begin(), areas.end());
  std::sort(expected.begin(), expected.end());
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(areas[k], expected[k], 1e-9);
  EXPECT_EQ(open_seams(s, s, 20, 20, 1e-9), 0);
  // Bent (the copies of each crease point coincide, as with exact stitching), the patches still
  // meet along their creases.
  const TrimmedSurface folded = trimmed_surface(m.fine, bent(m.fine));
  EXPECT_EQ(folded.triangle_count(), s.triangle_count());
  EXPECT_EQ(open_seams(folded, s, 20, 20, 1e-9), 0);
}

TEST(TrimmedSurface, AHoleIsLeftOpen) {
  CreasePattern p = rectangle_pattern(100, 100);
  p.sheet.holes.push_back(
      {{50, 30}, {30, 50}, {50, 70}, {70, 50}});  // clockwise, vertices on grid lines
  const DogModel m = build_dog_model(p, {11, 11});
  const TrimmedSurface s = trimmed_surface(m.fine, m.fine.V);
  EXPECT_NEAR(surface_area(s), mesh_area(m.fine, 100 * 100 - 800), 1e-9);
  for (int t = 0; t < s.triangle_count(); ++t) {
    const Eigen::Vector3d c =
        (s.V.row(s.T(t, 0)) + s.V.row(s.T(t, 1)) + s.V.row(s.T(t, 2))).transpose() / 3;
    EXPECT_GT(std::abs(c.x() - 5) + std::abs(c.y() - 5), 2 - 1e-9)
        << "triangle " << t << " lies in the hole";
  }
}

TEST(TrimmedSurface, SeamsCloseOnABentCurvedCrease) {
  // A circular crease around the centre: its cells are cut in every direction.
  Polyline2 circle;
  for (int k = 0; k < 64; ++k)
    circle.push_back({50 + 30 * std::cos(k * M_PI / 32), 50 + 30 * std::sin(k * M_PI / 32)});
  const DogModel m = build_dog_model(rectangle_pattern(100, 100, {circle}, {true}), {21, 21});
  const TrimmedSurface flat = trimmed_surface(m.fine, m.fine.V);
  EXPECT_NEAR(surface_area(flat), mesh_area(m.fine, 100 * 100), 1e-9);
  // The inner patch has the area of the snapped circle: within 1% of the drawn polygon's.
  const auto areas = patch_areas(m.fine, flat);
  const double inner = std::min(areas[0], areas[1]);
  EXPECT_NEAR(inner, mesh_area(m.fine, std::abs(signed_area(circle))), 0.01 * inner);
  EXPECT_EQ(open_seams(flat, flat, 20, 20, 1e-9), 0);
  EXPECT_EQ(open_seams(trimmed_surface(m.fine, bent(m.fine)), flat, 20, 20, 1e-9), 0);
  // Bent: every copy of every crease point is a vertex of its patch's part of the surface.
  TrimmedSurface s = flat;
  const Eigen::MatrixX3d X = bent(m.fine);
  place_trimmed_surface(s, X);
  int copies = 0;
  for (const auto& point : m.fine.stitching.points)
    for (size_t c = 0; c < point.copies.size(); ++c) {
      const Eigen::Vector3d p = DogMesh::position(X, point.copies[c]);
      bool found = false;
      for (int r = 0; r < s.vertex_count() && !found; ++r)
        found =
            s.vertex_patch[r] == point.patches[c] && (s.V.row(r).transpose() - p).norm() < 1e-12;
      EXPECT_TRUE(found) << "a copy of crease point " << p.transpose();
      ++copies;
    }
  EXPECT_GT(copies, 0);
}

TEST(TrimmedSurface, ArraysAreInterpolatedAndCellArraysFollowTheirQuad) {
  const DogModel m = build_dog_model(rectangle_pattern(100, 100, {{{0, 20}, {100, 70}}}), {11, 11});
  MeshArrays arrays;
  NamedArray x{"x", {}, false}, patch{"patch", {}, true}, quad{"quad", {}, true};
  for (int v = 0; v < m.fine.vertex_count(); ++v) {
    x.values.push_back(m.fine.V(v, 0));
    patch.values.push_back(m.fine.vertex_patch[v]);
  }
  for (int q = 0; q < m.fine.quad_count(); ++q) quad.values.push_back(q);
  arrays.point = {x, patch};
  arrays.cell = {quad};
  const TrimmedSurface s = trimmed_surface(m.fine, m.fine.V);
  const MeshArrays out = trimmed_arrays(s, arrays);
  ASSERT_EQ(out.point.size(), 2u);
  ASSERT_EQ(out.cell.size(), 1u);
  for (int r = 0; r < s.vertex_count(); ++r) {
    EXPECT_NEAR(out.point[0].values[r], s.V(r, 0),
                1e-12);  // x is bilinear, so exactly interpolated
    EXPECT_EQ(out.point[1].values[r], s.vertex_patch[r]);
  }
  for (int t = 0; t < s.triangle_count(); ++t) {
    EXPECT_EQ(out.cell[0].values[t], s.triangle_quad[t]);
    // The triangle lies in its quad's cell (at rest).
    const Eigen::Vector3d c =
        (s.V.row(s.T(t, 0)) + s.V.row(s.T(t, 1)) + s.V.row(s.T(t, 2))).transpose() / 3;
    const Eigen::Vector3d lo = m.fine.V.row(m.fine.F(s.triangle_quad[t], 0)),
                          hi = m.fine.V.row(m.fine.F(s.triangle_quad[t], 2));
    EXPECT_TRUE(c.x() >= lo.x() && c.x() <= hi.x() && c.y() >= lo.y() && c.y() <= hi.y());
  }
}

// Every dataset and reference pattern at rest: the trimmed surface covers the sheet once, fine and
// coarse (the snapped boundary and creases are within a fraction of a cell of the drawing).
TEST(TrimmedSurface, EveryPatternAtRestHasTheSheetsArea) {
  std::vector<std::string> patterns = test::all_datasets();
  for (const auto& p : test::all_reference_patterns()) patterns.push_back(p);
  for (const auto& path : patterns) {
    const DogModel m = build_dog_model(read_crease_pattern(path), {41, 41});
    const double expected = sheet_area(m);
    const double fine = surface_area(trimmed_surface(m.fine, m.fine.V));
    EXPECT_NEAR(fine, expected, 0.005 * expected) << path;
    if (m.has_coarse) {
      const double coarse = surface_area(trimmed_surface(m.coarse, m.coarse.V));
      EXPECT_NEAR(coarse, expected, 0.005 * expected) << path << " (coarse)";
    }
  }
}

}  // namespace
}  // namespace sdog
