// Terms restricted to a patch (patch_term.h): the blocks inside the patch, re-indexed.
#include <gtest/gtest.h>

#include "solver/patches/patch_term.h"
#include "tests/solver/patch_case.h"

namespace sdog {
namespace {

using test::PatchCase;

TEST(PatchTerm, KeepsTheBlocksInsideThePatchReindexed) {
  const PatchCase s("four_corner_arcs.svg", {15, 15});
  const DogMesh& mesh = s.model.fine;
  const Term& dog = s.problem->dog;
  const Dofs x = s.bent();
  int total = 0;
  for (int p = 0; p < mesh.patch_count(); ++p) {
    const int begin = mesh.patch_begin[p], end = mesh.patch_begin[p + 1];
    const PatchTerm view(dog, begin, end);
    total += view.block_count();
    for (int b = 0; b < view.block_count(); ++b) {
      const int src = view.source_block(b);
      ASSERT_EQ(view.block_size(b), dog.block_size(src));
      std::vector<Eigen::Vector3d> p1(view.block_size(b));
      for (int j = 0; j < view.block_size(b); ++j) {
        const int v = view.block_vertices(b)[j];
        ASSERT_GE(v, 0);
        ASSERT_LT(v, end - begin);
        ASSERT_EQ(v + begin, dog.block_vertices(src)[j]);
        p1[j] = vertex_of(x, v + begin);
      }
      Eigen::VectorXd r1(view.residual_count(b)), r2(view.residual_count(b));
      view.evaluate(b, p1.data(), r1.data(), nullptr);
      dog.evaluate(src, p1.data(), r2.data(), nullptr);
      EXPECT_EQ(r1, r2);
    }
  }
  EXPECT_EQ(total, dog.block_count());  // DOG constraints never cross patches
}

}  // namespace
}  // namespace sdog
