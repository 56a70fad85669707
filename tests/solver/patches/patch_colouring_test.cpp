// Colours of the patch graph (patch_colouring.h): stitched neighbours never share a colour, and
// greedy colouring stays within the largest neighbour count + 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/patches/patch_colouring.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

class PatchColouring : public ::testing::TestWithParam<const char*> {};

TEST_P(PatchColouring, NeighboursGetDifferentColours) {
  const DogModel m = build_dog_model(read_crease_pattern(test::dataset(GetParam())), {21, 21});
  const DogMesh& mesh = m.fine;
  const std::vector<int> colour = colour_patches(mesh);
  ASSERT_EQ(colour.size(), size_t(mesh.patch_count()));
  std::vector<std::set<int>> neighbours(mesh.patch_count());
  for (const auto& pair : mesh.stitching.pairs) {
    const auto& copies = mesh.stitching.points[pair.point].copies;
    const int a = mesh.vertex_patch[copies[pair.a].v1], b = mesh.vertex_patch[copies[pair.b].v1];
    if (a == b) continue;
    EXPECT_NE(colour[a], colour[b]) << "patches " << a << " and " << b;
    neighbours[a].insert(b);
    neighbours[b].insert(a);
  }
  size_t degree = 0;
  for (const auto& n : neighbours) degree = std::max(degree, n.size());
  EXPECT_GE(*std::min_element(colour.begin(), colour.end()), 0);
  EXPECT_LE(*std::max_element(colour.begin(), colour.end()), static_cast<int>(degree));
}

INSTANTIATE_TEST_SUITE_P(Datasets, PatchColouring,
                         ::testing::Values("four_corner_arcs.svg", "crossing_creases.svg",
                                           "four_parallel_curves.svg"));

TEST(PatchColouring, FourCornerArcsNeedsTwoColours) {
  // The central patch against the four corner patches.
  const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {21, 21});
  const std::vector<int> colour = colour_patches(m.fine);
  EXPECT_EQ(*std::max_element(colour.begin(), colour.end()), 1);
}

}  // namespace
}  // namespace sdog
