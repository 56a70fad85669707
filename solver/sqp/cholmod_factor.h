#pragma once
// CHOLMOD's supernodal Cholesky factorisation of the SQP solver's matrix K (lower triangle), set
// up once for a sparsity pattern. The only place that includes CHOLMOD.
#include <Eigen/Sparse>
#include <memory>
#include <string>

namespace sdog {

/// "MAJOR.MINOR.PATCH" of the CHOLMOD the program was built with.
std::string cholmod_version();

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
