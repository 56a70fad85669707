#pragma once
// Residual blocks: every energy term and the DOG constraints are sums over small blocks, each a
// few vertices with a few residual rows. One definition per term serves the Newton-KKT backend
// (values, Jacobians, second derivatives scattered into sparse matrices) and Ceres (one cost
// function per block; see ceres_cost.h).
//
// Unknowns: all vertex positions, x[3 v + c] (interleaved per vertex).
// A block's Jacobian is m x 3k, row-major, column 3 j + c for its j-th vertex, coordinate c.
#include <Eigen/Core>
#include <initializer_list>
#include <vector>

namespace sdog {

using Dofs = Eigen::VectorXd;

inline Eigen::Map<const Eigen::Vector3d> vertex_of(const Dofs& x, int v) {
  return Eigen::Map<const Eigen::Vector3d>(x.data() + 3 * v);
}

/// n x 3 positions <-> interleaved vector.
Dofs to_dofs(const Eigen::MatrixX3d& V);
Eigen::MatrixX3d to_positions(const Dofs& x);

class Term {
 public:
  virtual ~Term() = default;
  virtual const char* name() const = 0;

  int block_count() const { return static_cast<int>(offsets_.size()) - 1; }
  int block_size(int b) const { return offsets_[b + 1] - offsets_[b]; }
  const int* block_vertices(int b) const { return vertices_.data() + offsets_[b]; }
  int residual_count(int b) const { return rows_[b]; }
  int max_block_size() const { return max_size_; }
  int max_residual_count() const { return max_rows_; }

  /// Residuals r (and the Jacobian J if not null) of block b; p[j] is the position of its j-th
  /// vertex.
  virtual void evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const = 0;

  /// True when the residuals are affine in the positions (constant Jacobian, no curvature).
  virtual bool is_linear() const { return false; }

  /// Adds sum_i y_i * Hessian(r_i) (3k x 3k, row-major) to H. Terms without curvature information
  /// (Gauss-Newton) leave H unchanged.
  virtual void add_second_order(int /*b*/, const Eigen::Vector3d* /*p*/, const double* /*y*/,
                                double* /*H*/) const {}
  virtual bool has_second_order() const { return false; }

  /// The y to use for the exact Hessian of the squared residuals, 2 (J^T J + sum_i y_i H_i):
  /// y = r, unless the term keeps it positive semi-definite (isometry clamps).
  virtual void curvature_weights(int b, const double* r, double* y) const {
    for (int i = 0; i < residual_count(b); ++i) y[i] = r[i];
  }

 protected:
  void add_block(const int* vertices, int count, int rows);
  void add_block(std::initializer_list<int> vertices, int rows) {
    add_block(vertices.begin(), static_cast<int>(vertices.size()), rows);
  }
  void clear_blocks();

 private:
  std::vector<int> offsets_{0}, vertices_, rows_;
  int max_size_ = 0, max_rows_ = 0;
};

/// Positions of the vertices of block b, gathered from x.
void gather_block(const Term& term, int b, const Dofs& x, Eigen::Vector3d* p);

}  // namespace sdog
