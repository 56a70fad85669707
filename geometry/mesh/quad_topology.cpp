#include "geometry/mesh/quad_topology.h"

#include <algorithm>
#include <stdexcept>

namespace sdog {

int QuadTopology::count(VertexClass c) const {
  return static_cast<int>(std::count(vertex_class.begin(), vertex_class.end(), c));
}

QuadTopology quad_topology(const DogMesh& mesh) {
  const int n = mesh.vertex_count();
  QuadTopology topo;
  topo.neighbors.assign(n, {-1, -1, -1, -1});
  topo.quads_around.assign(n, 0);
  for (int q = 0; q < mesh.quad_count(); ++q) {
    for (int k = 0; k < 4; ++k) {
      const int a = mesh.F(q, k), b = mesh.F(q, (k + 1) % 4);
      ++topo.quads_around[a];
      const Eigen::Vector2i d = mesh.grid[b] - mesh.grid[a];
      const int dir_ab = d.x() > 0   ? kXForward
                         : d.x() < 0 ? kXBackward
                         : d.y() > 0 ? kYForward
                                     : kYBackward;
      topo.neighbors[a][dir_ab] = b;
      topo.neighbors[b][(dir_ab + 2) % 4] = a;
      topo.edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(topo.edges.begin(), topo.edges.end());
  topo.edges.erase(std::unique(topo.edges.begin(), topo.edges.end()), topo.edges.end());
  topo.vertex_class.resize(n);
  for (int v = 0; v < n; ++v) {
    const int nb = static_cast<int>(std::count_if(
        topo.neighbors[v].begin(), topo.neighbors[v].end(), [](int u) { return u >= 0; }));
    if (topo.quads_around[v] == 4)
      topo.vertex_class[v] = VertexClass::kStar;
    else if (nb == 4)
      topo.vertex_class[v] = VertexClass::kBnd4;
    else if (nb == 3)
      topo.vertex_class[v] = VertexClass::kBnd3;
    else if (nb == 2)
      topo.vertex_class[v] = VertexClass::kBnd2;
    else
      throw std::logic_error("vertex " + std::to_string(v) + " has " + std::to_string(nb) +
                             " neighbours");
  }
  return topo;
}

}  // namespace sdog
