#pragma once
// A symmetric 3n x 3n sparse matrix made of 3x3 vertex blocks, kept as its lower triangle in
// compressed-column form (what CHOLMOD factorises). The pattern is built once from the vertex sets
// that interact; afterwards values are refilled in place, so symbolic factorisations stay valid.
#include <Eigen/Sparse>
#include <vector>

#include "solver/terms/term.h"

namespace sdog {

class SymmetricBlockMatrix {
 public:
  /// Every pair of vertices within one block of one of the terms gets a 3x3 block; the diagonal
  /// blocks of all vertices always exist.
  SymmetricBlockMatrix(int vertex_count, const std::vector<const Term*>& terms);

  void set_zero();
  /// Adds a dense symmetric matrix H (3k x 3k, row-major) over the block's k vertices, scaled.
  void add_dense(const int* vertices, int k, const double* H, double scale);
  /// Adds scale * J^T J for a dense Jacobian J (m x 3k, row-major) over k vertices.
  void add_gram(const int* vertices, int k, const double* J, int m, double scale);
  /// Adds delta to every diagonal entry.
  void add_diagonal(double delta);
  /// Copies the values of another matrix with the same pattern.
  void copy_values(const SymmetricBlockMatrix& other);
  /// The value array of the lower triangle (pattern fixed), for in-place refills.
  double* mutable_values() { return m_.valuePtr(); }
  /// y = A x (A symmetric; both triangles).
  Eigen::VectorXd multiply(const Eigen::VectorXd& x) const;

  const Eigen::SparseMatrix<double>& lower() const { return m_; }
  int vertex_count() const { return static_cast<int>(rows_of_.size()); }

 private:
  // Position of row vertex a >= b among column vertex b's row vertices (b itself is 0).
  int rank(int a, int b) const;
  // Index in the value array of entry (row 3a + r, column 3b + c) for a >= b.
  int slot(int a, int b, int r, int c) const;
  std::vector<std::vector<int>> rows_of_;  // per column vertex b: sorted row vertices a >= b
  std::vector<int> diagonal_;              // slots of the 3n diagonal entries
  Eigen::SparseMatrix<double> m_;
};

}  // namespace sdog
