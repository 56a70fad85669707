// The alternative coarse DOG (the fine DOG without every second grid row and column) and its map,
// checked on every dataset and reference pattern, and on patterns whose outcome is known by hand.
#include "geometry/mesh/alt_coarse.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "tests/geometry/mesh/mesh_assets.h"
#include "tests/geometry/pattern_builders.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

DogModel alt_model(const CreasePattern& pattern, const Resolution& res) {
  MeshOptions options;
  options.coarse = CoarseKind::kAlt;
  return build_dog_model(pattern, res, options);
}

using Asset = test::MeshAsset;

std::vector<Asset> assets() {
  std::vector<Asset> out;
  for (const auto& p : test::all_datasets())
    for (Resolution r : {Resolution{21, 21}, Resolution{41, 31}}) out.push_back({p, r});
  for (const auto& p : test::all_reference_patterns()) out.push_back({p, {41, 41}});
  return out;
}

const DogModel& model(const Asset& a) {
  return test::cached_model(a, CoarseKind::kAlt);
}

class AltCoarse : public ::testing::TestWithParam<Asset> {};

TEST_P(AltCoarse, EveryCoarseVertexIsALinkAtItsFineTwin) {
  const DogModel& m = model(GetParam());
  EXPECT_EQ(m.coarse_kind, CoarseKind::kAlt);
  EXPECT_EQ(m.map.coarse_only_count, 0);
  ASSERT_GT(m.coarse.vertex_count(), 0);
  for (int c = 0; c < m.coarse.vertex_count(); ++c) {
    EXPECT_EQ(m.map.coarse_type[c], VertexType::kLink);
    const int f = m.map.coarse_to_fine[c];
    ASSERT_GE(f, 0) << "coarse vertex " << c;
    EXPECT_EQ(m.map.fine_to_coarse[f], c);
    EXPECT_EQ(m.fine.V.row(f), m.coarse.V.row(c));
    EXPECT_EQ(m.fine.vertex_patch[f], m.coarse.vertex_patch[c]);
    EXPECT_EQ(m.fine.grid[f], 2 * m.coarse.grid[c]);
  }
}

TEST_P(AltCoarse, EachCoarseQuadIsFourFineQuadsOfItsPatch) {
  const DogModel& m = model(GetParam());
  for (int q = 0; q < m.coarse.quad_count(); ++q) {
    const int p = m.coarse.vertex_patch[m.coarse.F(q, 0)];
    for (int k = 0; k < 4; ++k) {
      const int a = m.coarse.F(q, k), b = m.coarse.F(q, (k + 1) % 4);
      EXPECT_EQ(m.coarse.vertex_patch[a], p);
      // The fine midpoint of each side is an I vertex of the patch mapped to that side.
      const Eigen::Vector2i mid =
          m.fine.grid[m.map.coarse_to_fine[a]] / 2 + m.fine.grid[m.map.coarse_to_fine[b]] / 2;
      const int f = m.fine.vertex_at(p, mid.x(), mid.y());
      ASSERT_GE(f, 0) << "coarse quad " << q;
      const auto edge = m.map.fine_to_coarse_edge[f];
      EXPECT_TRUE((edge[0] == a && edge[1] == b) || (edge[0] == b && edge[1] == a));
    }
    const Eigen::Vector2i centre =
        m.fine.grid[m.map.coarse_to_fine[m.coarse.F(q, 0)]] + Eigen::Vector2i(1, 1);
    const int x = m.fine.vertex_at(p, centre.x(), centre.y());
    ASSERT_GE(x, 0);
    EXPECT_EQ(m.map.fine_to_coarse_quad[x], q);
    const Eigen::Vector3d a = m.coarse.V.row(m.coarse.F(q, 0)),
                          b = m.coarse.V.row(m.coarse.F(q, 1)),
                          c = m.coarse.V.row(m.coarse.F(q, 2));
    EXPECT_GT((b - a).cross(c - a).z(), 0.0) << "counter-clockwise";
  }
}

TEST_P(AltCoarse, FineVerticesAreTypedByParityAndCoveredOnlyWhereTheCoarseMeshIs) {
  const DogModel& m = model(GetParam());
  int uncovered = 0;
  for (int f = 0; f < m.fine.vertex_count(); ++f) {
    const int i = m.fine.grid[f].x(), j = m.fine.grid[f].y();
    const VertexType expected = i % 2 == 0 && j % 2 == 0   ? VertexType::kLink
                                : i % 2 == 1 && j % 2 == 1 ? VertexType::kX
                                                           : VertexType::kI;
    EXPECT_EQ(m.map.fine_type[f], expected);
    const int refs = (m.map.fine_to_coarse[f] >= 0) + (m.map.fine_to_coarse_edge[f][0] >= 0) +
                     (m.map.fine_to_coarse_quad[f] >= 0);
    EXPECT_LE(refs, 1);
    uncovered += refs == 0;
    if (m.map.fine_to_coarse_edge[f][0] >= 0) {
      const auto [a, b] = m.map.fine_to_coarse_edge[f];
      EXPECT_LT((m.fine.V.row(f) - 0.5 * (m.coarse.V.row(a) + m.coarse.V.row(b))).norm(), 1e-9);
    }
  }
  EXPECT_EQ(uncovered, m.map.uncovered_count);
  EXPECT_EQ(m.map.link_count + m.map.i_count + m.map.x_count, m.fine.vertex_count());
}

TEST_P(AltCoarse, KeptCreasePointsLieOnCoarseEdgesAndAreStitchedAsInTheFineMesh) {
  const DogModel& m = model(GetParam());
  const auto& cs = m.coarse.stitching;
  for (size_t k = 0; k < cs.points.size(); ++k) {
    const auto& p = cs.points[k];
    ASSERT_GE(p.copies.size(), 2u);
    for (size_t c = 0; c < p.copies.size(); ++c) {
      const EdgePoint& e = p.copies[c];
      EXPECT_LT((DogMesh::position(m.coarse.V, e).head<2>() - p.flat).norm(), 1e-9);
      EXPECT_EQ(m.coarse.vertex_patch[e.v1], p.patches[c]);
      EXPECT_EQ(m.coarse.vertex_patch[e.v2], p.patches[c]);
      if (e.v1 != e.v2) {
        const auto& nb = m.coarse_topology.neighbors[e.v1];
        EXPECT_NE(std::find(nb.begin(), nb.end(), e.v2), nb.end()) << "a coarse quad edge";
      }
    }
  }
  // A fine crease point is kept exactly when each copy lies on a coarse vertex or on a fine edge
  // from a covered link vertex to a covered I vertex of its coarse edge.
  const auto& fs = m.fine.stitching;
  int kept = 0;
  for (const auto& p : fs.points) {
    bool all = true;
    for (const EdgePoint& e : p.copies) {
      const int l = m.map.fine_type[e.v1] == VertexType::kLink ? e.v1 : e.v2;
      const int i = l == e.v1 ? e.v2 : e.v1;
      const bool on_vertex = e.v1 == e.v2 && m.map.fine_to_coarse[e.v1] >= 0;
      const auto edge = m.map.fine_to_coarse_edge[i];
      const bool on_edge =
          m.map.fine_type[l] == VertexType::kLink && m.map.fine_to_coarse[l] >= 0 && edge[0] >= 0 &&
          (edge[0] == m.map.fine_to_coarse[l] || edge[1] == m.map.fine_to_coarse[l]);
      all = all && (on_vertex || (e.v1 != e.v2 && on_edge));
    }
    kept += all;
  }
  EXPECT_EQ(kept, static_cast<int>(cs.points.size()));
  for (const auto& pair : cs.pairs)
    EXPECT_EQ((DogMesh::position(m.coarse.V, cs.points[pair.point].copies[pair.a]) -
               DogMesh::position(m.coarse.V, cs.points[pair.point].copies[pair.b]))
                  .norm(),
              0.0);
}

TEST_P(AltCoarse, OnlyTheEndsOfAnOpenCreaseCannotBeInterpolated) {
  const DogModel& m = model(GetParam());
  const auto& fs = m.fine.stitching;
  const auto& cs = m.coarse.stitching;
  ASSERT_EQ(m.map.curves.size(), fs.curves.size());
  for (size_t k = 0; k < fs.curves.size(); ++k) {
    const auto& corr = m.map.curves[k];
    ASSERT_EQ(corr.size(), fs.curves[k].points.size());
    int first = -1, last = -1, next = 0;
    for (size_t f = 0; f < corr.size(); ++f)
      if (corr[f].coarse >= 0) {
        EXPECT_EQ(corr[f].coarse, next++);
        EXPECT_EQ(fs.points[fs.curves[k].points[f]].flat,
                  cs.points[cs.curves[k].points[corr[f].coarse]].flat);
        if (first < 0) first = static_cast<int>(f);
        last = static_cast<int>(f);
      }
    EXPECT_EQ(next, static_cast<int>(cs.curves[k].points.size()));
    for (int f = 0; f < static_cast<int>(corr.size()); ++f) {
      const bool outside = first < 0 || f < first || f > last;
      if (corr[f].coarse >= 0) continue;
      if (fs.curves[k].closed && first >= 0) {
        EXPECT_GE(corr[f].segment, 0) << "closed crease " << k << " point " << f;
      } else {
        EXPECT_EQ(corr[f].segment < 0, outside) << "crease " << k << " point " << f;
      }
      if (corr[f].segment >= 0) {
        EXPECT_GT(corr[f].fraction, 0.0);
        EXPECT_LT(corr[f].fraction, 1.0);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllAssets, AltCoarse, ::testing::ValuesIn(assets()),
                         [](const auto& info) { return test::asset_name(info.param); });

// A crease along a grid column crosses the even rows between two fine columns: one patch has the
// coarse edge there, the other does not reach across the crease, so no crease point is kept and
// the coarse patches are not stitched (the thesis's disconnect, in its simplest form).
TEST(AltCoarseByHand, AStraightCreaseAcrossTheRowsKeepsNoPoint) {
  const DogModel m =
      alt_model(test::rectangle_pattern(100, 100, {{{52.5, 0}, {52.5, 100}}}), {21, 21});
  ASSERT_EQ(m.fine.stitching.curves.size(), 1u);
  EXPECT_GT(m.fine.stitching.curves[0].points.size(), 10u);
  EXPECT_TRUE(m.coarse.stitching.points.empty());
  EXPECT_TRUE(m.coarse.stitching.pairs.empty());
  const CurveCoverage c = curve_coverage(m.map);
  EXPECT_EQ(c.kept, 0);
  EXPECT_EQ(c.uninterpolable, static_cast<int>(m.fine.stitching.curves[0].points.size()));
  // The crease runs between fine columns 10 (x = 50) and 11 (x = 55). The left patch owns fine
  // cells 0..10 and so coarse cells up to coarse column 5; the right patch owns fine cells 10..19,
  // coarse cells from coarse column 5, whose edges from column 5 to 6 cross the crease: the point
  // lies on a coarse edge of the right patch only.
  EXPECT_EQ(m.coarse.patch_count(), 2);
  for (int v = 0; v < m.coarse.vertex_count(); ++v) {
    if (m.coarse.vertex_patch[v] == 0) EXPECT_LE(m.coarse.grid[v].x(), 5);
    if (m.coarse.vertex_patch[v] == 1) EXPECT_GE(m.coarse.grid[v].x(), 5);
  }
}

// A diagonal crease crosses some even grid lines on coarse edges that both patches own: those
// points are kept; its ends on the boundary are not (the thesis's observation).
TEST(AltCoarseByHand, ADiagonalCreaseKeepsPointsInsideAndNotAtItsEnds) {
  const DogModel m = alt_model(test::rectangle_pattern(100, 100, {{{0, 1}, {100, 99}}}), {21, 21});
  const CurveCoverage c = curve_coverage(m.map);
  EXPECT_GT(c.kept, 0);
  EXPECT_GT(c.uninterpolable, 0);
  const auto& corr = m.map.curves[0];
  EXPECT_LT(corr.front().segment, 0) << "the crease's first end is not kept";
  EXPECT_LT(corr.back().segment, 0) << "nor its last";
  EXPECT_FALSE(m.coarse.stitching.pairs.empty());
}

// The thesis: "the ends of each crease are not among them" on its patterns.
TEST(AltCoarseByHand, TheThesisPatternsKeepNoCreaseEnd) {
  SDOG_REQUIRE_SHARED();
  for (const char* name : {"1_curve.svg", "4_corners.svg", "2_curve.svg", "wave_mitani.svg"}) {
    const DogModel m =
        alt_model(read_crease_pattern(test::reference_patterns_dir() + "/" + name), {41, 41});
    for (size_t k = 0; k < m.map.curves.size(); ++k) {
      if (m.fine.stitching.curves[k].closed) continue;
      EXPECT_LT(m.map.curves[k].front().segment, 0) << name << " crease " << k;
      EXPECT_LT(m.map.curves[k].back().segment, 0) << name << " crease " << k;
    }
  }
}

}  // namespace
}  // namespace sdog
