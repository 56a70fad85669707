#include "solver/terms/isometry.h"

#include <algorithm>
#include <cmath>

namespace sdog {

IsometryTerm::IsometryTerm(const QuadTopology& topology, const Dofs& rest) {
  for (const auto& e : topology.edges) {
    add_block({e[0], e[1]}, 1);
    rest_squared_.push_back((vertex_of(rest, e[0]) - vertex_of(rest, e[1])).squaredNorm());
  }
}

void IsometryTerm::evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const {
  const Eigen::Vector3d d = p[0] - p[1];
  r[0] = d.squaredNorm() - rest_squared_[b];
  if (!J) return;
  for (int c = 0; c < 3; ++c) {
    J[c] = 2 * d[c];
    J[3 + c] = -2 * d[c];
  }
}

void IsometryTerm::add_second_order(int, const Eigen::Vector3d*, const double* y, double* H) const {
  for (int c = 0; c < 3; ++c) {
    H[c * 6 + c] += 2 * y[0];
    H[(3 + c) * 6 + 3 + c] += 2 * y[0];
    H[c * 6 + 3 + c] -= 2 * y[0];
    H[(3 + c) * 6 + c] -= 2 * y[0];
  }
}

void IsometryTerm::curvature_weights(int, const double* r, double* y) const {
  y[0] = std::max(r[0], 0.0);
}

}  // namespace sdog
