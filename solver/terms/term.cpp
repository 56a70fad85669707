#include "solver/terms/term.h"

#include <algorithm>

namespace sdog {

Dofs to_dofs(const Eigen::MatrixX3d& V) {
  Dofs x(3 * V.rows());
  for (Eigen::Index v = 0; v < V.rows(); ++v) x.segment<3>(3 * v) = V.row(v).transpose();
  return x;
}

Eigen::MatrixX3d to_positions(const Dofs& x) {
  Eigen::MatrixX3d V(x.size() / 3, 3);
  for (Eigen::Index v = 0; v < V.rows(); ++v) V.row(v) = x.segment<3>(3 * v).transpose();
  return V;
}

void Term::add_block(const int* vertices, int count, int rows) {
  vertices_.insert(vertices_.end(), vertices, vertices + count);
  offsets_.push_back(static_cast<int>(vertices_.size()));
  rows_.push_back(rows);
  max_size_ = std::max(max_size_, count);
  max_rows_ = std::max(max_rows_, rows);
}

void Term::clear_blocks() {
  offsets_.assign(1, 0);
  vertices_.clear();
  rows_.clear();
  max_size_ = max_rows_ = 0;
}

void gather_block(const Term& term, int b, const Dofs& x, Eigen::Vector3d* p) {
  const int* v = term.block_vertices(b);
  for (int j = 0; j < term.block_size(b); ++j) p[j] = vertex_of(x, v[j]);
}

}  // namespace sdog
