// The quantities an SQP step is built from: objective, gradient and Hessian, constraint values,
// Jacobian and curvature, and the factorisation of K = H + rho J^T J + delta I.
#include <cmath>

#include "base/stopwatch.h"
#include "solver/sqp/cholmod_factor.h"
#include "solver/sqp/sqp_solver.h"

namespace sdog {
namespace {

// K is made positive definite by raising rho (by this factor, up to the pass's cap), then the
// shift, at most this many times.
constexpr double kRhoGrowth = 10;
constexpr double kShiftGrowth = 10;
constexpr double kSmallestRaisedShift = 1e-8;
constexpr int kFactorizationAttempts = 24;

}  // namespace

void SqpSolver::set_weight(size_t term, double weight) {
  if (objective_[term].weight == weight) return;
  objective_[term].weight = weight;
  if (objective_[term].term->is_linear()) m_.constant_dirty = true;
}

void SqpSolver::refresh_constant_hessian() {
  m_.constant.set_zero();
  std::vector<double> J, r;
  std::vector<Eigen::Vector3d> p;
  const Dofs zero = Dofs::Zero(3 * n_);
  for (const auto& wt : objective_) {
    const Term& t = *wt.term;
    if (!t.is_linear() || wt.weight == 0) continue;
    for (int b = 0; b < t.block_count(); ++b) {
      const int k = t.block_size(b), m = t.residual_count(b);
      p.resize(k);
      r.resize(m);
      J.resize(static_cast<size_t>(m) * 3 * k);
      gather_block(t, b, zero, p.data());
      t.evaluate(b, p.data(), r.data(), J.data());
      m_.constant.add_gram(t.block_vertices(b), k, J.data(), m, 2 * wt.weight);
    }
  }
  m_.constant_dirty = false;
}

double SqpSolver::objective(const Dofs& x, std::vector<double>* unweighted) const {
  double f = 0;
  std::vector<double> r;
  std::vector<Eigen::Vector3d> p;
  if (unweighted) unweighted->assign(objective_.size(), 0.0);
  for (size_t k = 0; k < objective_.size(); ++k) {
    const Term& t = *objective_[k].term;
    double sum = 0;
    for (int b = 0; b < t.block_count(); ++b) {
      p.resize(t.block_size(b));
      r.resize(t.residual_count(b));
      gather_block(t, b, x, p.data());
      t.evaluate(b, p.data(), r.data(), nullptr);
      for (double v : r) sum += v * v;
    }
    if (unweighted) (*unweighted)[k] = sum;
    f += objective_[k].weight * sum;
  }
  return f;
}

Eigen::VectorXd SqpSolver::constraint_values(const Dofs& x) const {
  Eigen::VectorXd c(rows_.count);
  std::vector<Eigen::Vector3d> p;
  for (int b = 0; b < constraints_.block_count(); ++b) {
    p.resize(constraints_.block_size(b));
    gather_block(constraints_, b, x, p.data());
    constraints_.evaluate(b, p.data(), c.data() + rows_.first[b], nullptr);
  }
  return c;
}

double SqpSolver::augmented_lagrangian(const Dofs& x, double rho) const {
  const Eigen::VectorXd c = constraint_values(x);
  return objective(x) - lambda_.dot(c) + 0.5 * rho * c.squaredNorm();
}

double SqpSolver::kkt_error(const Linearization& lin) const {
  const double grad = (lin.g - lin.J.transpose() * lambda_).lpNorm<Eigen::Infinity>();
  return std::max(grad, lin.c.lpNorm<Eigen::Infinity>());
}

void SqpSolver::linearize(const Dofs& x, Linearization& lin, bool hessian, bool curvature) {
  if (m_.constant_dirty) refresh_constant_hessian();
  lin.f = 0;
  lin.g = Eigen::VectorXd::Zero(3 * n_);
  std::vector<double> r, y, J, Hb;
  std::vector<Eigen::Vector3d> p;
  if (hessian) {
    m_.H.copy_values(m_.constant);
    m_.G.set_zero();
  }
  for (const auto& wt : objective_) {
    const Term& t = *wt.term;
    if (wt.weight == 0) continue;
    for (int b = 0; b < t.block_count(); ++b) {
      const int k = t.block_size(b), m = t.residual_count(b), cols = 3 * k;
      p.resize(k);
      r.resize(m);
      J.resize(static_cast<size_t>(m) * cols);
      gather_block(t, b, x, p.data());
      t.evaluate(b, p.data(), r.data(), J.data());
      const int* v = t.block_vertices(b);
      for (int i = 0; i < m; ++i) {
        lin.f += wt.weight * r[i] * r[i];
        for (int j = 0; j < k; ++j)
          for (int c = 0; c < 3; ++c)
            lin.g[3 * v[j] + c] += 2 * wt.weight * J[i * cols + 3 * j + c] * r[i];
      }
      if (!hessian || t.is_linear()) continue;
      m_.H.add_gram(v, k, J.data(), m, 2 * wt.weight);
      if (wt.exact_hessian && t.has_second_order()) {
        y.resize(m);
        t.curvature_weights(b, r.data(), y.data());
        Hb.assign(static_cast<size_t>(cols) * cols, 0.0);
        t.add_second_order(b, p.data(), y.data(), Hb.data());
        m_.H.add_dense(v, k, Hb.data(), 2 * wt.weight);
      }
    }
  }
  fill_constraints(x, lin.c, lin.J, hessian, curvature);
}

bool SqpSolver::relinearize(const Dofs& x, Linearization& lin, SqpReport& report) {
  const auto t = Clock::now();
  linearize(x, lin, false, false);
  report.work.assembly_ms += ms_since(t);
  return std::isfinite(lin.f) && lin.g.allFinite() && lin.c.allFinite();
}

void SqpSolver::fill_constraints(const Dofs& x, Eigen::VectorXd& c, RowMatrix& J, bool hessian,
                                 bool curvature) {
  c.resize(rows_.count);
  J = rows_.pattern;
  double* values = J.valuePtr();
  std::vector<double> Jb, y, Hb;
  std::vector<Eigen::Vector3d> p;
  const Term& t = constraints_;
  for (int b = 0; b < t.block_count(); ++b) {
    const int k = t.block_size(b), m = t.residual_count(b), cols = 3 * k;
    const int first = rows_.first[b];
    p.resize(k);
    Jb.resize(static_cast<size_t>(m) * cols);
    gather_block(t, b, x, p.data());
    t.evaluate(b, p.data(), c.data() + first, Jb.data());
    for (int i = 0; i < m; ++i) {
      double* row = values + J.outerIndexPtr()[first + i];
      for (int j = 0; j < k; ++j)
        for (int e = 0; e < 3; ++e) row[3 * rows_.column_rank[b][j] + e] = Jb[i * cols + 3 * j + e];
    }
    if (!hessian) continue;
    const int* v = t.block_vertices(b);
    m_.G.add_gram(v, k, Jb.data(), m, 1.0);
    if (!curvature) continue;
    y.resize(m);
    for (int i = 0; i < m; ++i) y[i] = -lambda_[first + i];
    Hb.assign(static_cast<size_t>(cols) * cols, 0.0);
    t.add_second_order(b, p.data(), y.data(), Hb.data());
    m_.H.add_dense(v, k, Hb.data(), 1.0);
  }
}

SqpSolver::Linearization SqpSolver::linearization(const Dofs& x, double rho,
                                                  Eigen::SparseMatrix<double>* K) {
  Linearization lin;
  linearize(x, lin, K != nullptr, options_.lagrangian_hessian);
  if (K) {
    *K = m_.H.lower();
    *K += rho * m_.G.lower();
  }
  return lin;
}

bool SqpSolver::refactorize(const Dofs& x, Linearization& lin, double epsilon, bool curvature,
                            double rho_cap, SqpReport& report) {
  const auto t_asm = Clock::now();
  linearize(x, lin, true, curvature);
  report.work.assembly_ms += ms_since(t_asm);
  factored_ = false;
  if (!m_.H.lower().coeffs().allFinite() || !m_.G.lower().coeffs().allFinite()) return false;
  factored_J_ = lin.J;
  const auto t0 = Clock::now();
  // K = H + rho J^T J must be positive definite. Where it is not, H is indefinite across the
  // constraints (only with the constraints' curvature): raise rho up to the cap first, then the
  // shift.
  rho_ = 1 / epsilon;
  auto assemble = [&]() {
    const double* h = m_.H.lower().valuePtr();
    const double* g = m_.G.lower().valuePtr();
    double* k = m_.K.mutable_values();
    for (Eigen::Index i = 0; i < m_.K.lower().nonZeros(); ++i) k[i] = h[i] + rho_ * g[i];
  };
  assemble();
  for (int attempt = 0; attempt < kFactorizationAttempts; ++attempt) {
    const bool injected = injected_failures_ > 0 && injected_failures_-- > 0;
    if (!injected && factor_->factorize(m_.K.lower(), delta_)) {
      ++report.work.factorizations;
      ++factorizations_;
      report.work.factor_ms += ms_since(t0);
      factored_ = true;
      return true;
    }
    if (rho_ < rho_cap) {
      rho_ = std::min(kRhoGrowth * rho_, rho_cap);
      assemble();
    } else {
      delta_ = std::max(kShiftGrowth * delta_, kSmallestRaisedShift);
    }
  }
  report.work.factor_ms += ms_since(t0);
  return false;
}

Eigen::VectorXd SqpSolver::solve(const Eigen::VectorXd& rhs, SqpReport& report) const {
  const auto t0 = Clock::now();
  Eigen::VectorXd d = factor_->solve(rhs);
  report.work.factor_ms += ms_since(t0);
  return d;
}

}  // namespace sdog
