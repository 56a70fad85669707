#include "solver/terms/linear_point_term.h"

#include <algorithm>
#include <stdexcept>

namespace sdog {

int LinearPointTerm::add(const std::vector<std::pair<int, double>>& weighted_vertices,
                         const Eigen::Vector3d& target) {
  std::vector<std::pair<int, double>> merged;
  for (const auto& [v, a] : weighted_vertices) {
    auto it =
        std::find_if(merged.begin(), merged.end(), [v = v](const auto& m) { return m.first == v; });
    if (it == merged.end())
      merged.push_back({v, a});
    else
      it->second += a;
  }
  merged.erase(
      std::remove_if(merged.begin(), merged.end(), [](const auto& m) { return m.second == 0; }),
      merged.end());
  if (merged.size() > kMaxVertices)
    throw std::logic_error("linear point block with too many vertices");
  std::vector<int> vertices;
  for (const auto& [v, a] : merged) {
    vertices.push_back(v);
    coefficients_.push_back(a);
  }
  offsets_.push_back(static_cast<int>(coefficients_.size()));
  targets_.push_back(target);
  add_block(vertices.data(), static_cast<int>(vertices.size()), 3);
  return block_count() - 1;
}

void LinearPointTerm::clear() {
  clear_blocks();
  coefficients_.clear();
  offsets_.assign(1, 0);
  targets_.clear();
}

void LinearPointTerm::evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const {
  const double* pp[kMaxVertices];
  const int k = block_size(b);
  for (int j = 0; j < k; ++j) pp[j] = p[j].data();
  residual<double>(b, pp, r);
  if (!J) return;
  const int cols = 3 * k;
  std::fill(J, J + 3 * cols, 0.0);
  for (int j = 0; j < k; ++j)
    for (int c = 0; c < 3; ++c) J[c * cols + 3 * j + c] = coefficient(b, j);
}

}  // namespace sdog
