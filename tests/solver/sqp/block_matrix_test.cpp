// The symmetric block matrix the SQP solver assembles its Hessians in: every entry that add_dense
// and add_gram add lands where a dense matrix would have it.
#include <gtest/gtest.h>

#include <random>

#include "solver/sqp/block_matrix.h"
#include "solver/terms/linear_point_term.h"

namespace sdog {
namespace {

using Dense = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A term with blocks of two to four vertices, given in no particular order, over 9 vertices.
LinearPointTerm some_blocks() {
  LinearPointTerm t("test blocks");
  t.add({{4, 1.0}, {1, -1.0}});
  t.add({{8, 0.5}, {0, 0.25}, {5, 0.25}});
  t.add({{2, 1.0}, {7, 1.0}, {3, -1.0}, {6, -1.0}});
  t.add({{6, 1.0}, {2, -1.0}});
  return t;
}

// Adds scale * H (3k x 3k over the vertices) to a dense 3n x 3n matrix.
void scatter(Dense& A, const std::vector<int>& vertices, const Dense& H, double scale) {
  for (size_t i = 0; i < vertices.size(); ++i)
    for (size_t j = 0; j < vertices.size(); ++j)
      A.block<3, 3>(3 * vertices[i], 3 * vertices[j]) += scale * H.block<3, 3>(3 * i, 3 * j);
}

TEST(SymmetricBlockMatrix, AddDenseAndAddGramPlaceEveryEntry) {
  const LinearPointTerm t = some_blocks();
  SymmetricBlockMatrix M(9, {&t});
  Dense expected = Dense::Zero(27, 27);
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0, 1);
  for (int b = 0; b < t.block_count(); ++b) {
    const int k = t.block_size(b);
    const std::vector<int> vertices(t.block_vertices(b), t.block_vertices(b) + k);
    Dense R(3 * k, 3 * k), J(2, 3 * k);
    for (int i = 0; i < R.size(); ++i) R.data()[i] = n(rng);
    for (int i = 0; i < J.size(); ++i) J.data()[i] = n(rng);
    const Dense H = R + R.transpose();
    M.add_dense(vertices.data(), k, H.data(), 0.5);
    scatter(expected, vertices, H, 0.5);
    M.add_gram(vertices.data(), k, J.data(), 2, 3.0);
    scatter(expected, vertices, J.transpose() * J, 3.0);
  }
  const Dense got = Dense(M.lower()).selfadjointView<Eigen::Lower>();
  EXPECT_LT((got - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 1.0);
  // Only the lower triangle is stored.
  const Dense stored = M.lower();
  EXPECT_EQ(stored.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().cwiseAbs().maxCoeff(),
            0.0);
}

}  // namespace
}  // namespace sdog
