#include "solver/sqp/block_matrix.h"

#include <algorithm>
#include <stdexcept>

namespace sdog {

SymmetricBlockMatrix::SymmetricBlockMatrix(int vertex_count, const std::vector<const Term*>& terms)
    : rows_of_(vertex_count) {
  for (int v = 0; v < vertex_count; ++v) rows_of_[v].push_back(v);
  for (const Term* t : terms)
    for (int b = 0; b < t->block_count(); ++b) {
      const int* vs = t->block_vertices(b);
      for (int i = 0; i < t->block_size(b); ++i)
        for (int j = 0; j < t->block_size(b); ++j)
          if (vs[i] > vs[j]) rows_of_[vs[j]].push_back(vs[i]);
    }
  for (auto& rows : rows_of_) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  }
  // Column 3b + c holds the lower part of the diagonal block (rows 3b + c .. 3b + 2), then three
  // rows for every row vertex a > b.
  const int n = 3 * vertex_count;
  m_.resize(n, n);
  std::vector<int> outer(n + 1, 0);
  for (int b = 0; b < vertex_count; ++b)
    for (int c = 0; c < 3; ++c)
      outer[3 * b + c + 1] =
          outer[3 * b + c] + (3 - c) + 3 * (static_cast<int>(rows_of_[b].size()) - 1);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(outer[n]);
  for (int b = 0; b < vertex_count; ++b)
    for (int c = 0; c < 3; ++c)
      for (int a : rows_of_[b])
        for (int r = (a == b ? c : 0); r < 3; ++r) entries.emplace_back(3 * a + r, 3 * b + c, 0.0);
  m_.setFromTriplets(entries.begin(), entries.end());
  m_.makeCompressed();
  diagonal_.resize(n);
  for (int b = 0; b < vertex_count; ++b)
    for (int c = 0; c < 3; ++c) diagonal_[3 * b + c] = slot(b, b, c, c);
}

int SymmetricBlockMatrix::rank(int a, int b) const {
  const auto& rows = rows_of_[b];
  return static_cast<int>(std::lower_bound(rows.begin(), rows.end(), a) - rows.begin());
}

// Column 3b + c holds rows 3b + c .. 3b + 2 of the diagonal block (rank 0), then rows 3a .. 3a + 2
// of each row vertex a of rank 1, 2, ...: entry (3a + r, 3b + c) is 3 rank + r - c past the
// column's start.
int SymmetricBlockMatrix::slot(int a, int b, int r, int c) const {
  return m_.outerIndexPtr()[3 * b + c] + 3 * rank(a, b) + r - c;
}

void SymmetricBlockMatrix::set_zero() {
  std::fill(m_.valuePtr(), m_.valuePtr() + m_.nonZeros(), 0.0);
}

void SymmetricBlockMatrix::add_dense(const int* vertices, int k, const double* H, double scale) {
  double* values = m_.valuePtr();
  const int* outer = m_.outerIndexPtr();
  const int cols = 3 * k;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const int a = vertices[i], b = vertices[j];
      if (a < b) continue;
      const int position = 3 * rank(a, b);  // as in slot(), looked up once for the whole block
      for (int c = 0; c < 3; ++c) {
        double* column = values + outer[3 * b + c] + position - c;
        for (int r = (a == b ? c : 0); r < 3; ++r)
          column[r] += scale * H[(3 * i + r) * cols + 3 * j + c];
      }
    }
}

void SymmetricBlockMatrix::add_gram(const int* vertices, int k, const double* J, int m,
                                    double scale) {
  // Small dense J^T J (at most 3k <= 48 columns).
  const int cols = 3 * k;
  if (k > 16) throw std::logic_error("block with more than 16 vertices");
  double G[48 * 48];
  for (int p = 0; p < cols; ++p)
    for (int q = 0; q <= p; ++q) {
      double s = 0;
      for (int i = 0; i < m; ++i) s += J[i * cols + p] * J[i * cols + q];
      G[p * cols + q] = G[q * cols + p] = s;
    }
  add_dense(vertices, k, G, scale);
}

void SymmetricBlockMatrix::add_diagonal(double delta) {
  for (int s : diagonal_) m_.valuePtr()[s] += delta;
}

void SymmetricBlockMatrix::copy_values(const SymmetricBlockMatrix& other) {
  std::copy(other.m_.valuePtr(), other.m_.valuePtr() + m_.nonZeros(), m_.valuePtr());
}

Eigen::VectorXd SymmetricBlockMatrix::multiply(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y = m_.selfadjointView<Eigen::Lower>() * x;
  return y;
}

}  // namespace sdog
