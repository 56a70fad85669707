#include "solver/terms/bending.h"

namespace sdog {

LinearPointTerm make_bending_term(const QuadTopology& topology, const Dofs& rest) {
  LinearPointTerm term("bending");
  const int n = static_cast<int>(topology.vertex_class.size());
  for (int v = 0; v < n; ++v) {
    const auto& nb = topology.neighbors[v];
    std::vector<std::pair<int, double>> coefficients;
    auto add_neighbour = [&](int u, double scale) {
      const double inv = scale / (vertex_of(rest, v) - vertex_of(rest, u)).norm();
      coefficients.push_back({v, inv});
      coefficients.push_back({u, -inv});
    };
    if (topology.vertex_class[v] == VertexClass::kStar) {
      for (int u : nb) add_neighbour(u, 1.0);
    } else if (topology.vertex_class[v] == VertexClass::kBnd3) {
      // The missing direction is opposite the inner neighbour; the other two lie on the boundary.
      int missing = 0;
      while (nb[missing] >= 0) ++missing;
      add_neighbour(nb[(missing + 1) % 4], 2.0);
      add_neighbour(nb[(missing + 3) % 4], 2.0);
    } else {
      continue;
    }
    term.add(coefficients);
  }
  return term;
}

}  // namespace sdog
