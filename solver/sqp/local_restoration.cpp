#include "solver/sqp/local_restoration.h"

#include <Eigen/SparseCholesky>
#include <algorithm>

namespace sdog {

LocalRestoration::LocalRestoration(int vertex_count, const Term& constraints, int rings)
    : constraints_(constraints), rings_(rings), vertex_blocks_(vertex_count) {
  int row = 0;
  for (int b = 0; b < constraints.block_count(); ++b) {
    first_row_.push_back(row);
    for (int i = 0; i < constraints.residual_count(b); ++i) row_block_.push_back(b);
    row += constraints.residual_count(b);
    for (int j = 0; j < constraints.block_size(b); ++j)
      vertex_blocks_[constraints.block_vertices(b)[j]].push_back(b);
  }
}

std::vector<int> LocalRestoration::neighbourhood(const Eigen::VectorXd& c, double tolerance) const {
  std::vector<char> in(vertex_blocks_.size(), 0);
  std::vector<int> frontier;
  auto add_block = [&](int b) {
    for (int j = 0; j < constraints_.block_size(b); ++j) {
      const int v = constraints_.block_vertices(b)[j];
      if (!in[v]) {
        in[v] = 1;
        frontier.push_back(v);
      }
    }
  };
  for (Eigen::Index i = 0; i < c.size(); ++i)
    if (std::abs(c[i]) > tolerance) add_block(row_block_[i]);
  for (int ring = 0; ring < rings_; ++ring) {
    std::vector<int> current;
    current.swap(frontier);
    for (int v : current)
      for (int b : vertex_blocks_[v]) add_block(b);
  }
  std::vector<int> vertices;
  for (size_t v = 0; v < in.size(); ++v)
    if (in[v]) vertices.push_back(static_cast<int>(v));
  return vertices;
}

bool LocalRestoration::step(const std::vector<int>& vertices, const Eigen::VectorXd& c,
                            const Eigen::SparseMatrix<double, Eigen::RowMajor>& J,
                            const Eigen::SparseMatrix<double>& H, double rho, double delta,
                            Eigen::VectorXd& d) const {
  if (vertices.empty()) return false;
  // Local dof numbering, increasing with the global one (keeps H's lower triangle lower).
  std::vector<int> local(J.cols(), -1);
  int m = 0;
  for (int v : vertices)
    for (int k = 0; k < 3; ++k) local[3 * v + k] = m++;
  // Rows whose block touches the neighbourhood.
  std::vector<char> block_used(first_row_.size(), 0);
  std::vector<int> rows;
  for (int v : vertices)
    for (int b : vertex_blocks_[v])
      if (!block_used[b]) {
        block_used[b] = 1;
        for (int i = 0; i < constraints_.residual_count(b); ++i) rows.push_back(first_row_[b] + i);
      }
  std::vector<Eigen::Triplet<double>> jt;
  Eigen::VectorXd cr(rows.size());
  for (size_t r = 0; r < rows.size(); ++r) {
    cr[r] = c[rows[r]];
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(J, rows[r]); it; ++it)
      if (local[it.col()] >= 0) jt.emplace_back(static_cast<int>(r), local[it.col()], it.value());
  }
  Eigen::SparseMatrix<double> Jl(static_cast<Eigen::Index>(rows.size()), m);
  Jl.setFromTriplets(jt.begin(), jt.end());
  std::vector<Eigen::Triplet<double>> ht;
  for (int v : vertices)
    for (int k = 0; k < 3; ++k) {
      const int col = 3 * v + k;
      for (Eigen::SparseMatrix<double>::InnerIterator it(H, col); it; ++it)
        if (local[it.row()] >= 0) ht.emplace_back(local[it.row()], local[col], it.value());
      ht.emplace_back(local[col], local[col], delta);
    }
  Eigen::SparseMatrix<double> K(m, m);
  K.setFromTriplets(ht.begin(), ht.end());
  const Eigen::SparseMatrix<double> JtJ = Eigen::SparseMatrix<double>(Jl.transpose()) * Jl;
  K += rho * Eigen::SparseMatrix<double>(JtJ.triangularView<Eigen::Lower>());
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt(K);
  if (llt.info() != Eigen::Success) return false;
  const Eigen::VectorXd dl = llt.solve(-rho * (Jl.transpose() * cr));
  if (!dl.allFinite()) return false;
  d = Eigen::VectorXd::Zero(J.cols());
  for (int v : vertices)
    for (int k = 0; k < 3; ++k) d[3 * v + k] = dl[local[3 * v + k]];
  return true;
}

}  // namespace sdog
