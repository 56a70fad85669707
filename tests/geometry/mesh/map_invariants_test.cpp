// Properties of the fine mesh, the coarse mesh and the map, checked on every dataset and every
// reference pattern (a geometry-central style fixture over all assets).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <map>

#include "base/errors.h"
#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "tests/geometry/mesh/mesh_assets.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

using Asset = test::MeshAsset;

std::vector<Asset> assets() {
  std::vector<Asset> out;
  for (const auto& p : test::all_datasets())
    for (Resolution r : {Resolution{21, 21}, Resolution{41, 31}, Resolution{61, 61}})
      out.push_back({p, r});
  for (const auto& p : test::all_reference_patterns())
    for (Resolution r : {Resolution{41, 41}, Resolution{61, 45}}) out.push_back({p, r});
  return out;
}

const DogModel& model(const Asset& a) {
  return test::cached_model(a);
}

class MapInvariants : public ::testing::TestWithParam<Asset> {
 protected:
  double tol() const { return 1e-9 * (model(GetParam()).fine.xs.back() + 1); }
};

TEST_P(MapInvariants, LinkedVerticesCoincideInTheFlatState) {
  const DogModel& m = model(GetParam());
  int links = 0;
  for (int f = 0; f < m.fine.vertex_count(); ++f) {
    const int c = m.map.fine_to_coarse[f];
    if (c < 0) continue;
    ++links;
    EXPECT_EQ(m.fine.V.row(f), m.coarse.V.row(c)) << "fine " << f << " coarse " << c;
    EXPECT_EQ(m.map.coarse_to_fine[c], f);
    EXPECT_EQ(m.fine.vertex_patch[f], m.coarse.vertex_patch[c]);
  }
  EXPECT_EQ(links, m.map.link_count);
  EXPECT_GT(links, 0);
}

TEST_P(MapInvariants, IVerticesAreMidpointsOfTheirCoarseEdge) {
  const DogModel& m = model(GetParam());
  for (int f = 0; f < m.fine.vertex_count(); ++f) {
    if (m.map.fine_type[f] != VertexType::kI) continue;
    const auto [a, b] = m.map.fine_to_coarse_edge[f];
    ASSERT_GE(a, 0);
    ASSERT_GE(b, 0);
    const Eigen::RowVector3d mid = 0.5 * (m.coarse.V.row(a) + m.coarse.V.row(b));
    EXPECT_LT((m.fine.V.row(f) - mid).norm(), tol()) << "fine vertex " << f;
    // The coarse edge is a quad edge of the coarse mesh.
    const auto& nb = m.coarse_topology.neighbors[a];
    EXPECT_NE(std::find(nb.begin(), nb.end(), b), nb.end()) << "coarse " << a << "-" << b;
  }
}

TEST_P(MapInvariants, XVerticesAreCentresOfTheirCoarseQuad) {
  const DogModel& m = model(GetParam());
  for (int f = 0; f < m.fine.vertex_count(); ++f) {
    if (m.map.fine_type[f] != VertexType::kX) continue;
    const int q = m.map.fine_to_coarse_quad[f];
    ASSERT_GE(q, 0);
    Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k) centre += 0.25 * m.coarse.V.row(m.coarse.F(q, k));
    EXPECT_LT((m.fine.V.row(f) - centre).norm(), tol()) << "fine vertex " << f;
    EXPECT_EQ(m.coarse.vertex_patch[m.coarse.F(q, 0)], m.fine.vertex_patch[f]);
  }
}

TEST_P(MapInvariants, EveryVertexHasExactlyOneConsistentLabel) {
  const DogModel& m = model(GetParam());
  int counts[4] = {0, 0, 0, 0};
  for (int f = 0; f < m.fine.vertex_count(); ++f) {
    const VertexType t = m.map.fine_type[f];
    ++counts[static_cast<int>(t)];
    EXPECT_NE(t, VertexType::kCoarseOnly);
    const bool link = m.map.fine_to_coarse[f] >= 0;
    const bool edge = m.map.fine_to_coarse_edge[f][0] >= 0;
    const bool quad = m.map.fine_to_coarse_quad[f] >= 0;
    EXPECT_EQ(link + edge + quad, 1) << "fine vertex " << f;
    EXPECT_EQ(link, t == VertexType::kLink);
    EXPECT_EQ(edge, t == VertexType::kI);
    EXPECT_EQ(quad, t == VertexType::kX);
  }
  EXPECT_EQ(counts[0] + counts[1] + counts[2], m.fine.vertex_count());
  EXPECT_EQ(counts[1], m.map.i_count);
  EXPECT_EQ(counts[2], m.map.x_count);
  int coarse_only = 0;
  for (int c = 0; c < m.coarse.vertex_count(); ++c) {
    const bool twin = m.map.coarse_to_fine[c] >= 0;
    EXPECT_EQ(twin, m.map.coarse_type[c] == VertexType::kLink);
    coarse_only += !twin;
  }
  EXPECT_EQ(coarse_only, m.map.coarse_only_count);
  EXPECT_EQ(m.map.link_count + coarse_only, m.coarse.vertex_count());
}

void check_stitching(const DogMesh& mesh, double tol) {
  const auto& st = mesh.stitching;
  for (size_t k = 0; k < st.points.size(); ++k) {
    const auto& p = st.points[k];
    EXPECT_GE(p.copies.size(), 2u) << "crease point " << k;
    for (size_t c = 0; c < p.copies.size(); ++c) {
      const Eigen::Vector3d pos = DogMesh::position(mesh.V, p.copies[c]);
      EXPECT_LT((pos.head<2>() - p.flat).norm(), tol);
      EXPECT_EQ(mesh.vertex_patch[p.copies[c].v1], p.patches[c]);
      EXPECT_EQ(mesh.vertex_patch[p.copies[c].v2], p.patches[c]);
      EXPECT_GE(p.copies[c].t, 0.0);
      EXPECT_LE(p.copies[c].t, 1.0);
    }
  }
  for (const auto& pair : st.pairs) {
    const auto& p = st.points[pair.point];
    const Eigen::Vector3d r =
        DogMesh::position(mesh.V, p.copies[pair.a]) - DogMesh::position(mesh.V, p.copies[pair.b]);
    EXPECT_EQ(r.norm(), 0.0) << "stitching residual of point " << pair.point;
  }
}

TEST_P(MapInvariants, CreasePointsHaveTwoCopiesAndZeroFlatStitchingResidual) {
  const DogModel& m = model(GetParam());
  check_stitching(m.fine, tol());
  check_stitching(m.coarse, tol());
}

TEST_P(MapInvariants, VertexClassesAddUpAndPatchesAreContiguous) {
  const DogModel& m = model(GetParam());
  for (const auto* pair : {&m.fine, &m.coarse}) {
    const DogMesh& mesh = *pair;
    const QuadTopology& t = pair == &m.fine ? m.fine_topology : m.coarse_topology;
    EXPECT_EQ(t.count(VertexClass::kStar) + t.count(VertexClass::kBnd3) +
                  t.count(VertexClass::kBnd2) + t.count(VertexClass::kBnd4),
              mesh.vertex_count());
    EXPECT_EQ(mesh.patch_begin.back(), mesh.vertex_count());
    for (int p = 0; p < mesh.patch_count(); ++p) {
      EXPECT_LT(mesh.patch_begin[p], mesh.patch_begin[p + 1]) << "empty patch " << p;
      for (int v = mesh.patch_begin[p]; v < mesh.patch_begin[p + 1]; ++v)
        EXPECT_EQ(mesh.vertex_patch[v], p);
      for (int q = mesh.quad_patch_begin[p]; q < mesh.quad_patch_begin[p + 1]; ++q)
        for (int k = 0; k < 4; ++k) EXPECT_EQ(mesh.vertex_patch[mesh.F(q, k)], p);
    }
    for (int q = 0; q < mesh.quad_count(); ++q) {  // counter-clockwise with y up
      const Eigen::Vector3d a = mesh.V.row(mesh.F(q, 0)), b = mesh.V.row(mesh.F(q, 1)),
                            c = mesh.V.row(mesh.F(q, 2));
      EXPECT_GT((b - a).cross(c - a).z(), 0.0);
    }
  }
  EXPECT_EQ(m.fine.patch_count(), m.expected_patches);
  EXPECT_EQ(m.coarse.patch_count(), m.expected_patches);
}

TEST_P(MapInvariants, CoarseCreasePointsAreFineOnesWithMonotoneFractions) {
  const DogModel& m = model(GetParam());
  const auto& fs = m.fine.stitching;
  const auto& cs = m.coarse.stitching;
  ASSERT_EQ(m.map.curves.size(), fs.curves.size());
  for (size_t k = 0; k < fs.curves.size(); ++k) {
    const auto& corr = m.map.curves[k];
    ASSERT_EQ(corr.size(), fs.curves[k].points.size());
    int expected_coarse = 0;
    double last_fraction = 0;
    for (size_t f = 0; f < corr.size(); ++f) {
      if (corr[f].coarse >= 0) {
        EXPECT_EQ(corr[f].coarse, expected_coarse++);
        EXPECT_EQ(fs.points[fs.curves[k].points[f]].flat,
                  cs.points[cs.curves[k].points[corr[f].coarse]].flat);
        last_fraction = 0;
      } else {
        EXPECT_EQ(corr[f].segment, expected_coarse - 1);
        EXPECT_GT(corr[f].fraction, last_fraction);
        EXPECT_LT(corr[f].fraction, 1.0);
        last_fraction = corr[f].fraction;
      }
    }
    EXPECT_EQ(expected_coarse, static_cast<int>(cs.curves[k].points.size()));
  }
}

INSTANTIATE_TEST_SUITE_P(AllAssets, MapInvariants, ::testing::ValuesIn(assets()),
                         [](const auto& info) { return test::asset_name(info.param); });

TEST(ReferencePatterns, EveryPatternBuildsOrFailsWithAClearMessage) {
  SDOG_REQUIRE_SHARED();
  for (const auto& p : test::all_reference_patterns()) {
    for (Resolution r : {Resolution{11, 11}, Resolution{21, 21}, Resolution{41, 41}}) {
      try {
        const DogModel m = build_dog_model(read_crease_pattern(p), r);
        EXPECT_EQ(m.fine.patch_count(), m.expected_patches) << p;
      } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("resolution"), std::string::npos)
            << p << ": " << e.what();
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(std::filesystem::path(p).filename().string()),
                  std::string::npos)
            << e.what();
      }
    }
  }
}

}  // namespace
}  // namespace sdog
