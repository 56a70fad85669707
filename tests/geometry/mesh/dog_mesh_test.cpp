// Meshes of patterns whose answer is known in closed form, and a property test of cell ownership
// against an independent rule for straight creases.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

#include "base/errors.h"
#include "geometry/mesh/dog_model.h"
#include "tests/geometry/pattern_builders.h"

namespace sdog {
namespace {

using test::rectangle_pattern;

TEST(DogMesh, PlainSheetIsOneGrid) {
  const DogModel m = build_dog_model(rectangle_pattern(300, 200), {11, 7});
  EXPECT_EQ(m.fine.vertex_count(), 77);
  EXPECT_EQ(m.fine.quad_count(), 60);
  EXPECT_EQ(m.fine.patch_count(), 1);
  EXPECT_EQ(m.fine_topology.count(VertexClass::kStar), 9 * 5);
  EXPECT_EQ(m.fine_topology.count(VertexClass::kBnd3), 2 * 9 + 2 * 5);
  EXPECT_EQ(m.fine_topology.count(VertexClass::kBnd2), 4);
  EXPECT_EQ(m.fine_topology.count(VertexClass::kBnd4), 0);
  // Mesh units: the x spacing is 1, the sheet's aspect ratio is kept.
  EXPECT_DOUBLE_EQ(m.fine.V(1, 0) - m.fine.V(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(m.fine.V(11, 1) - m.fine.V(0, 1), (200.0 / 6) * (10.0 / 300));
  EXPECT_EQ(m.coarse.vertex_count(), 6 * 4);
  EXPECT_EQ(m.map.link_count, 24);
  EXPECT_EQ(m.map.coarse_only_count, 0);
  EXPECT_EQ(m.map.x_count, 5 * 3);
}

TEST(DogMesh, CreaseAlongAGridLineDuplicatesOnlyThatLine) {
  // Lines at 0, 25, 50, 75, 100; the crease runs along x = 50.
  const DogModel m = build_dog_model(rectangle_pattern(100, 100, {{{50, 0}, {50, 100}}}), {5, 5});
  EXPECT_EQ(m.fine.patch_count(), 2);
  EXPECT_EQ(m.fine.quad_count(), 16);
  EXPECT_EQ(m.fine.vertex_count(), 30);
  EXPECT_EQ(m.fine.stitching.points.size(), 5u);
  for (const auto& p : m.fine.stitching.points) {
    ASSERT_EQ(p.copies.size(), 2u);
    EXPECT_EQ(p.copies[0].t, 1.0);
    EXPECT_EQ(p.copies[0].v1, p.copies[0].v2);
  }
  EXPECT_EQ(m.fine.stitching.pairs.size(), 5u);
}

TEST(DogMesh, DiagonalThroughGridVerticesCutsOnlyTheDiagonalCells) {
  for (int n : {5, 9, 21}) {
    const DogModel m = build_dog_model(rectangle_pattern(100, 100, {{{0, 0}, {100, 100}}}), {n, n});
    // Each half owns the cells below (above) the diagonal and the n-1 cut diagonal cells.
    EXPECT_EQ(m.fine.quad_count(), (n - 1) * (n - 1) + (n - 1)) << n;
    EXPECT_EQ(m.fine.vertex_count(), n * (n + 1) + 2 * (n - 1)) << n;
    EXPECT_EQ(m.fine.stitching.points.size(), static_cast<size_t>(n)) << n;
    EXPECT_EQ(m.fine.patch_count(), 2);
  }
}

TEST(DogMesh, CrossingCreasesMeetAtAPinnedGridVertexOfFourPatches) {
  // Two straight creases crossing at (37, 61): the junction becomes a grid vertex.
  const DogModel m = build_dog_model(
      rectangle_pattern(100, 100, {{{0, 61}, {100, 61}}, {{37, 0}, {37, 100}}}), {11, 11});
  EXPECT_EQ(m.fine.patch_count(), 4);
  EXPECT_EQ(m.clean.junctions.size(), 1u);
  ASSERT_EQ(m.fine.stitching.junctions.size(), 1u);
  const auto& j = m.fine.stitching.points[m.fine.stitching.junctions[0]];
  EXPECT_EQ(j.copies.size(), 4u);
  for (const auto& c : j.copies) EXPECT_EQ(c.v1, c.v2);
  EXPECT_EQ(j.flat, m.fine.to_mesh({37, 61}));
  // Coarse meshes keep the junction as a grid vertex too (nested grids).
  ASSERT_EQ(m.coarse.stitching.junctions.size(), 1u);
  EXPECT_EQ(m.coarse.stitching.points[m.coarse.stitching.junctions[0]].flat, j.flat);
}

// Straight creases snap to themselves, so a cell belongs to the patch on one side of the line iff
// one of its corners lies strictly on that side.
TEST(DogMesh, StraightCreaseCellOwnershipMatchesTheHalfPlaneRule) {
  std::mt19937 rng(12345);
  // Sizes divisible by every cell count used, so grid coordinates are integers and the test's
  // side computation is exact.
  const double W = 2520, H = 1680;
  const int cells[] = {4, 6, 8, 10, 12, 14, 20, 24, 28, 30, 40};
  for (int trial = 0; trial < 80; ++trial) {
    const int cx = cells[std::uniform_int_distribution<int>(0, 10)(rng)];
    const int cy = cells[std::uniform_int_distribution<int>(0, 10)(rng)];
    const int nx = cx + 1, ny = cy + 1;
    const double hx = W / cx, hy = H / cy;
    // End points on two different sides; every other trial on grid vertices.
    auto boundary_point = [&](int side) -> Eigen::Vector2d {
      const int lines = (side % 2 == 0) ? cx : cy;
      const double len = (side % 2 == 0) ? W : H;
      double t = std::uniform_real_distribution<double>(0.05, 0.95)(rng) * len;
      if (trial % 2 == 0)
        t = std::clamp(std::round(t / (len / lines)), 1.0, lines - 1.0) * (len / lines);
      switch (side) {
        case 0:
          return {t, 0};
        case 1:
          return {W, t};
        case 2:
          return {t, H};
        default:
          return {0, t};
      }
    };
    const int s0 = trial % 4, s1 = (s0 + 1 + (trial / 4) % 3) % 4;
    const Eigen::Vector2d a = boundary_point(s0), b = boundary_point(s1);
    const DogModel m = build_dog_model(rectangle_pattern(W, H, {{a, b}}), {nx, ny}, {{}, false});
    ASSERT_EQ(m.fine.patch_count(), 2);
    const DogMesh& mesh = m.fine;
    auto side = [&](double x, double y) {
      const long double s = static_cast<long double>(b.x() - a.x()) * (y - a.y()) -
                            static_cast<long double>(b.y() - a.y()) * (x - a.x());
      return s > 0 ? 1 : (s < 0 ? -1 : 0);
    };
    // The left patch owns a cell whose corners are all strictly on the left.
    std::map<std::pair<int, int>, std::set<int>> owners;
    for (int q = 0; q < mesh.quad_count(); ++q) {
      const auto g = mesh.grid[mesh.F(q, 0)];
      owners[{g.x(), g.y()}].insert(mesh.vertex_patch[mesh.F(q, 0)]);
    }
    // (Or the right patch one whose corners are all on the right, when the left side is small.)
    int left_patch = -1;
    for (const auto& [cell, who] : owners) {
      int sum = 0;
      for (int d = 0; d < 4; ++d)
        sum += side((cell.first + d % 2) * hx, (cell.second + d / 2) * hy);
      if (sum == 4) left_patch = *who.begin();
      if (sum == -4 && left_patch < 0) left_patch = 1 - *who.begin();
    }
    ASSERT_GE(left_patch, 0);
    std::set<std::tuple<int, int, int>> owned;
    for (const auto& [cell, who] : owners)
      for (int p : who) owned.insert({p == left_patch ? 1 : -1, cell.first, cell.second});
    for (int i = 0; i < cx; ++i)
      for (int j = 0; j < cy; ++j) {
        bool has[2] = {false, false};
        for (int di = 0; di < 2; ++di)
          for (int dj = 0; dj < 2; ++dj) {
            const int s = side((i + di) * hx, (j + dj) * hy);
            if (s > 0) has[0] = true;
            if (s < 0) has[1] = true;
          }
        EXPECT_EQ(owned.count({1, i, j}) > 0, has[0])
            << "trial " << trial << " cell " << i << "," << j;
        EXPECT_EQ(owned.count({-1, i, j}) > 0, has[1])
            << "trial " << trial << " cell " << i << "," << j;
      }
  }
}

}  // namespace
}  // namespace sdog

namespace sdog {
namespace {

TEST(DogMesh, TwoCreasePointsOnOneGridEdgeAreBothKept) {
  // Lines at x = 0, 25, ..., 100 and y = 0, 25, ...: the crease dips below y = 50 and comes back
  // between x = 30 and x = 45, so both crossings lie on the grid edge (25,50)-(50,50).
  const DogModel m =
      build_dog_model(test::rectangle_pattern(
                          100, 100, {{{0, 60}, {30, 52}, {35, 48}, {40, 48}, {45, 52}, {100, 60}}}),
                      {5, 5}, {{}, false});
  int on_edge = 0;
  std::set<double> ts;
  for (const auto& p : m.fine.stitching.points) {
    const Eigen::Vector2d sheet = p.flat / m.fine.scale + m.fine.sheet_origin;
    if (std::abs(sheet.y() - 50) < 1e-9 && sheet.x() > 25 && sheet.x() < 50) {
      ++on_edge;
      ts.insert(p.copies[0].t);
      EXPECT_EQ(p.copies.size(), 2u);
    }
  }
  EXPECT_EQ(on_edge, 2);
  EXPECT_EQ(ts.size(), 2u);
}

// The crease points of a mesh at `sheet` within `radius` sheet units.
std::vector<const CreaseStitching::Point*> points_near(const DogMesh& mesh,
                                                       const Eigen::Vector2d& sheet,
                                                       double radius) {
  std::vector<const CreaseStitching::Point*> near;
  for (const auto& p : mesh.stitching.points)
    if ((p.flat / mesh.scale + mesh.sheet_origin - sheet).norm() < radius) near.push_back(&p);
  return near;
}

TEST(DogMesh, CreaseTouchingAGridLineIsStitchedOnceWhereItTouches) {
  // Lines at 0, 25, 50, ...: the crease dips 0.001 below y = 50 between x = 37.45 and 37.55, so
  // it crosses the grid edge (25,50)-(50,50) twice, 0.1 sheet units (0.004 mesh units) apart, as a
  // flattened arc does where it touches a grid line.
  const DogModel m = build_dog_model(
      test::rectangle_pattern(
          100, 100, {{{0, 60}, {30, 52}, {37.45, 49.999}, {37.55, 49.999}, {45, 52}, {100, 60}}}),
      {5, 5});
  for (const DogMesh* mesh : {&m.fine, &m.coarse}) {
    const auto near = points_near(*mesh, {37.5, 50}, 1);
    ASSERT_EQ(near.size(), 1u) << (mesh == &m.fine ? "fine" : "coarse");
    EXPECT_EQ(near[0]->copies.size(), 2u);
  }
  // Both meshes keep the same one of the two crossings.
  EXPECT_EQ(points_near(m.fine, {37.5, 50}, 1)[0]->flat / m.fine.scale + m.fine.sheet_origin,
            points_near(m.coarse, {37.5, 50}, 1)[0]->flat / m.coarse.scale + m.coarse.sheet_origin);
}

TEST(DogMesh, PatchesAreNumberedByTheirFirstCellInRowMajorOrder) {
  const DogModel m = build_dog_model(
      test::rectangle_pattern(100, 100,
                              {{{0, 70}, {100, 20}}, {{60, 0}, {60, 100}}, {{0, 30}, {30, 0}}}),
      {21, 21});
  const int cells_x = m.fine.nx() - 1;
  int previous = -1;
  for (int p = 0; p < m.fine.patch_count(); ++p) {
    int first = INT32_MAX;
    for (int q = m.fine.quad_patch_begin[p]; q < m.fine.quad_patch_begin[p + 1]; ++q) {
      const auto g = m.fine.grid[m.fine.F(q, 0)];
      first = std::min(first, g.y() * cells_x + g.x());
    }
    EXPECT_GE(first, previous) << "patch " << p;
    previous = first;
  }
  // Patch 0 owns the bottom-left cell.
  EXPECT_EQ(m.fine.grid[m.fine.F(0, 0)], Eigen::Vector2i(0, 0));
}

// Eleven slanted creases crossed by one more: eleven junctions with distinct x and y, which the
// coarse grid holds from 13 lines on (a fine grid of 25), and no earlier.
TEST(DogMesh, TheLowestMeshingResolutionIsNarrowedDownBetweenSteps) {
  std::vector<Polyline2> creases;
  for (int i = 1; i <= 11; ++i) creases.push_back({{10.0 * i - 3, 0}, {10.0 * i + 3, 120}});
  creases.push_back({{0, 4}, {120, 116}});
  const CreasePattern p = rectangle_pattern(120, 120, creases);
  EXPECT_THROW(build_dog_model(p, {23, 23}), UsageError);
  EXPECT_NO_THROW(build_dog_model(p, {25, 25}));
  // The steps from 9x9 are 13, 15, 19, 23 and 29 lines; halving between 23 and 29 finds 25.
  const std::optional<Resolution> lowest = lowest_meshing_resolution(p, {9, 9});
  ASSERT_TRUE(lowest);
  EXPECT_EQ(lowest->nx, 25);
  EXPECT_EQ(lowest->ny, 25);
}

}  // namespace
}  // namespace sdog
