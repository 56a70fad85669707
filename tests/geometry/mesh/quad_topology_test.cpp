// Quad topology (quad_topology.h): neighbours and vertex classes.
#include <gtest/gtest.h>

#include "geometry/mesh/dog_mesh.h"
#include "geometry/mesh/dog_model.h"
#include "geometry/mesh/quad_topology.h"
#include "tests/geometry/pattern_builders.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

using test::rectangle_pattern;

TEST(QuadTopology, NeighboursAreInCyclicOrder) {
  const DogModel m = build_dog_model(rectangle_pattern(100, 100), {5, 5}, {{}, false});
  const int v = 2 * 5 + 2;  // centre vertex (2, 2)
  const auto& nb = m.fine_topology.neighbors[v];
  EXPECT_EQ(m.fine.grid[nb[kXForward]], Eigen::Vector2i(3, 2));
  EXPECT_EQ(m.fine.grid[nb[kYForward]], Eigen::Vector2i(2, 3));
  EXPECT_EQ(m.fine.grid[nb[kXBackward]], Eigen::Vector2i(1, 2));
  EXPECT_EQ(m.fine.grid[nb[kYBackward]], Eigen::Vector2i(2, 1));
  EXPECT_EQ(m.fine_topology.vertex_class[v], VertexClass::kStar);
  EXPECT_EQ(m.fine_topology.vertex_class[2], VertexClass::kBnd3);
  EXPECT_EQ(m.fine_topology.neighbors[2][kYBackward], -1);
  EXPECT_EQ(m.fine_topology.vertex_class[0], VertexClass::kBnd2);
  EXPECT_EQ(m.fine_topology.edges.size(), 2u * 4 * 5);
}

TEST(QuadTopology, StaircaseBoundariesHaveBnd4Vertices) {
  // A curved crease gives staircase patch boundaries: reflex corners are bnd4.
  const DogModel m = build_dog_model(
      rectangle_pattern(100, 100,
                        {{{0, 30}, {20, 32}, {40, 38}, {60, 50}, {80, 68}, {92, 85}, {100, 100}}}),
      {21, 21});
  EXPECT_GT(m.fine_topology.count(VertexClass::kBnd4), 0);
  for (int v = 0; v < m.fine.vertex_count(); ++v) {
    int nb = 0;
    for (int u : m.fine_topology.neighbors[v]) nb += u >= 0;
    if (m.fine_topology.vertex_class[v] == VertexClass::kBnd4) {
      EXPECT_EQ(nb, 4);
      EXPECT_LT(m.fine_topology.quads_around[v], 4);
    }
  }
}

}  // namespace
}  // namespace sdog
