#include "solver/sqp/cholmod_factor.h"

#include <Eigen/CholmodSupport>

namespace sdog {
namespace {

// Coarser supernodes than CHOLMOD's defaults ({4, 16, 48} / {0.8, 0.1, 0.05}): more explicit
// zeros, larger dense blocks for the BLAS, a faster numeric factorisation on these grids
// (docs/design/standard-solver.md).
constexpr int kRelaxedColumns[3] = {16, 64, 128};
constexpr double kRelaxedZeros[3] = {0.9, 0.2, 0.1};

}  // namespace

std::string cholmod_version() {
  return std::to_string(CHOLMOD_MAIN_VERSION) + "." + std::to_string(CHOLMOD_SUB_VERSION) + "." +
         std::to_string(CHOLMOD_SUBSUB_VERSION);
}

struct CholmodFactor::Impl {
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
};

CholmodFactor::CholmodFactor(const Eigen::SparseMatrix<double>& K)
    : impl_(std::make_unique<Impl>()) {
  cholmod_common& c = impl_->llt.cholmod();
  c.print = 0;  // libraries do not print
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_METIS;  // beats AMD on these grids
  for (int i = 0; i < 3; ++i) {
    c.nrelax[i] = kRelaxedColumns[i];
    c.zrelax[i] = kRelaxedZeros[i];
  }
  impl_->llt.analyzePattern(K);
}

CholmodFactor::~CholmodFactor() = default;

bool CholmodFactor::factorize(const Eigen::SparseMatrix<double>& K, double shift) {
  impl_->llt.setShift(shift);
  impl_->llt.factorize(K);
  return impl_->llt.info() == Eigen::Success;
}

Eigen::VectorXd CholmodFactor::solve(const Eigen::VectorXd& rhs) const {
  return impl_->llt.solve(rhs);
}

}  // namespace sdog
