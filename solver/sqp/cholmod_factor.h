#pragma once
// CHOLMOD's supernodal Cholesky factorisation of the SQP solver's matrix K (lower triangle), set
// up once for a sparsity pattern. Private to the sqp layer: the only place that includes CHOLMOD.
#include <Eigen/Sparse>
#include <memory>

namespace sdog {

class CholmodFactor {
 public:
  /// The symbolic analysis of K's pattern (METIS ordering, coarse supernodes).
  explicit CholmodFactor(const Eigen::SparseMatrix<double>& K);
  ~CholmodFactor();
  /// The numeric factorisation of K + shift I; false when K + shift I is not positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& K, double shift);
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sdog
