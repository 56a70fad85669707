// Fine-to-coarse restriction (restriction.h): exact for motions of the flat sheet, copies link
// vertices, and close to the coarse mesh a coarse run computes itself.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/multilevel/restriction.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

const DogModel& model() {
  static const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {21, 21});
  return m;
}

// x -> A x + b on every vertex.
Dofs moved(const Eigen::MatrixX3d& V, const Eigen::Matrix3d& A, const Eigen::Vector3d& b) {
  Dofs x(3 * V.rows());
  for (Eigen::Index v = 0; v < V.rows(); ++v) x.segment<3>(3 * v) = A * V.row(v).transpose() + b;
  return x;
}

TEST(Restriction, IsExactForAffineMotionsOfTheFlatSheet) {
  const DogModel& m = model();
  int coarse_only = 0;
  for (int c = 0; c < m.coarse.vertex_count(); ++c) coarse_only += m.map.coarse_to_fine[c] < 0;
  ASSERT_GT(coarse_only, 0) << "the test needs coarse-only vertices";
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::Matrix3d shear = R;
  shear(0, 1) += 0.3;
  for (const Eigen::Matrix3d& A : {R, shear}) {
    const Eigen::Vector3d b(4, -2, 7);
    const Dofs coarse = restrict_to_coarse(m, moved(m.fine.V, A, b));
    const Dofs expected = moved(m.coarse.V, A, b);
    EXPECT_LT((coarse - expected).lpNorm<Eigen::Infinity>(), 1e-9);
  }
}

TEST(Restriction, CopiesTheLinkVertices) {
  const DogModel& m = model();
  Dofs fine = Dofs::Random(3 * m.fine.vertex_count());
  const Dofs coarse = restrict_to_coarse(m, fine);
  int links = 0;
  for (int c = 0; c < m.coarse.vertex_count(); ++c) {
    const int f = m.map.coarse_to_fine[c];
    if (f < 0) continue;
    ++links;
    EXPECT_EQ(Eigen::Vector3d(vertex_of(coarse, c)), Eigen::Vector3d(vertex_of(fine, f)))
        << "coarse vertex " << c;
  }
  EXPECT_GT(links, m.coarse.vertex_count() / 2);
  EXPECT_TRUE(coarse.allFinite());
}

}  // namespace
}  // namespace sdog
