#include "solver/sqp/sqp_solver.h"

#include <algorithm>
#include <numeric>
#include <cmath>

#include "base/text_format.h"
#include "base/stopwatch.h"

namespace sdog {

std::string SqpOptions::validate() const {
  if (!(kkt_tolerance > 0)) return "kkt_tolerance must be positive";
  if (max_steps < 1) return "max_steps must be at least 1";
  if (!(epsilon > 0)) return "epsilon must be positive";
  if (!(restoration_epsilon > 0)) return "restoration_epsilon must be positive";
  if (!(merit_penalty > 0)) return "merit_penalty must be positive";
  if (trusted_backtracks < 0) return "trusted_backtracks must not be negative";
  if (!(constraint_tolerance > 0)) return "constraint_tolerance must be positive";
  if (!(final_constraint_tolerance > 0)) return "final_constraint_tolerance must be positive";
  if (polish_steps < 0) return "polish_steps must not be negative";
  if (max_restoration_steps < 0) return "max_restoration_steps must not be negative";
  if (local_rings < 0) return "local_rings must not be negative";
  if (!(local_fraction >= 0 && local_fraction <= 1)) return "local_fraction must be in [0, 1]";
  if (!(armijo > 0 && armijo < 0.5)) return "armijo must be in (0, 0.5)";
  if (max_backtracks < 0) return "max_backtracks must not be negative";
  if (!(regularization >= 0)) return "regularization must not be negative";
  if (!(polish_epsilon > 0)) return "polish_epsilon must be positive";
  if (!(rho_max >= 1 / epsilon) || !(rho_max >= 1 / restoration_epsilon) || !(rho_max >= 1 / polish_epsilon))
    return "rho_max must be at least 1/epsilon, 1/restoration_epsilon and 1/polish_epsilon";
  return "";
}

namespace {

// Sets a flag back to false when it leaves scope (the polishing flag, on every return path).
struct ClearOnExit {
  bool& flag;
  ~ClearOnExit() { flag = false; }
};

// Adds the work of `part` (a polish, a projection) to `total`.
void add_work(SqpReport& total, const SqpReport& part) {
  total.steps += part.steps;
  total.restoration_steps += part.restoration_steps;
  total.local_steps += part.local_steps;
  total.factorizations += part.factorizations;
  total.factor_ms += part.factor_ms;
  total.assembly_ms += part.assembly_ms;
}

// A chord restoration step is followed by another while it cuts |c|^2 at least this much, up to
// kMaxChords per iteration.
constexpr double kChordProgress = 0.8;
constexpr int kMaxChords = 5;

std::vector<const Term*> all_terms(const std::vector<WeightedTerm>& objective, const Term& constraints) {
  std::vector<const Term*> terms;
  for (const auto& t : objective) terms.push_back(t.term);
  terms.push_back(&constraints);
  return terms;
}

}  // namespace

SqpSolver::SqpSolver(int vertex_count, std::vector<WeightedTerm> objective, const Term& constraints,
                     const SqpOptions& options)
    : n_(vertex_count),
      objective_(std::move(objective)),
      constraints_(constraints),
      options_(options),
      constant_hessian_(vertex_count, all_terms(objective_, constraints)),
      H_(vertex_count, all_terms(objective_, constraints)),
      G_(vertex_count, all_terms(objective_, constraints)),
      K_(vertex_count, all_terms(objective_, constraints)),
      local_(vertex_count, constraints, options.local_rings) {
  rho_cap_ = options_.rho_max;
  for (int b = 0; b < constraints_.block_count(); ++b) {
    first_row_.push_back(rows_);
    rows_ += constraints_.residual_count(b);
  }
  lambda_ = Eigen::VectorXd::Zero(rows_);
  delta_ = options_.regularization;
  // Constraint Jacobian pattern: each row holds its block's vertices in increasing order.
  std::vector<Eigen::Triplet<double>> entries;
  column_rank_.resize(constraints_.block_count());
  for (int b = 0; b < constraints_.block_count(); ++b) {
    const int k = constraints_.block_size(b);
    const int* v = constraints_.block_vertices(b);
    for (int j = 0; j < k; ++j)
      column_rank_[b].push_back(static_cast<int>(std::count_if(v, v + k, [&](int u) { return u < v[j]; })));
    for (int i = 0; i < constraints_.residual_count(b); ++i)
      for (int j = 0; j < k; ++j)
        for (int e = 0; e < 3; ++e) entries.emplace_back(first_row_[b] + i, 3 * v[j] + e, 1.0);
  }
  J_pattern_.resize(rows_, 3 * n_);
  J_pattern_.setFromTriplets(entries.begin(), entries.end());
  J_pattern_.makeCompressed();
  llt_ = std::make_unique<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower>>();
  llt_->cholmod().print = 0;  // libraries do not print
  llt_->cholmod().nmethods = 1;
  llt_->cholmod().method[0].ordering = CHOLMOD_METIS;  // measured: beats AMD on these grids
  // Coarser supernodes (more explicit zeros, larger dense blocks for BLAS): measured 25% faster
  // numeric factorisation on the 81x81 grid than CHOLMOD's defaults {4, 16, 48} / {0.8, 0.1, 0.05}.
  const int nrelax[3] = {16, 64, 128};
  const double zrelax[3] = {0.9, 0.2, 0.1};
  for (int i = 0; i < 3; ++i) {
    llt_->cholmod().nrelax[i] = nrelax[i];
    llt_->cholmod().zrelax[i] = zrelax[i];
  }
  llt_->analyzePattern(K_.lower());
}

SqpSolver::~SqpSolver() = default;

void SqpSolver::set_weight(size_t term, double weight) {
  if (objective_[term].weight == weight) return;
  objective_[term].weight = weight;
  if (objective_[term].term->is_linear()) constant_dirty_ = true;
}

void SqpSolver::refresh_constant_hessian() {
  constant_hessian_.set_zero();
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
      constant_hessian_.add_gram(t.block_vertices(b), k, J.data(), m, 2 * wt.weight);
    }
  }
  constant_dirty_ = false;
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
  Eigen::VectorXd c(rows_);
  std::vector<Eigen::Vector3d> p;
  for (int b = 0; b < constraints_.block_count(); ++b) {
    p.resize(constraints_.block_size(b));
    gather_block(constraints_, b, x, p.data());
    constraints_.evaluate(b, p.data(), c.data() + first_row_[b], nullptr);
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

void SqpSolver::linearize(const Dofs& x, Linearization& lin, bool hessian) {
  if (constant_dirty_) refresh_constant_hessian();
  lin.f = 0;
  lin.g = Eigen::VectorXd::Zero(3 * n_);
  std::vector<double> r, y, J, Hb;
  std::vector<Eigen::Vector3d> p;
  if (hessian) {
    H_.copy_values(constant_hessian_);
    G_.set_zero();
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
          for (int c = 0; c < 3; ++c) lin.g[3 * v[j] + c] += 2 * wt.weight * J[i * cols + 3 * j + c] * r[i];
      }
      if (!hessian || t.is_linear()) continue;
      H_.add_gram(v, k, J.data(), m, 2 * wt.weight);
      if (wt.exact_hessian && t.has_second_order()) {
        y.resize(m);
        t.curvature_weights(b, r.data(), y.data());
        Hb.assign(static_cast<size_t>(cols) * cols, 0.0);
        t.add_second_order(b, p.data(), y.data(), Hb.data());
        H_.add_dense(v, k, Hb.data(), 2 * wt.weight);
      }
    }
  }
  fill_constraints(x, lin.c, lin.J, hessian);
}

void SqpSolver::fill_constraints(const Dofs& x, Eigen::VectorXd& c, RowMatrix& J, bool hessian) {
  c.resize(rows_);
  J = J_pattern_;
  double* values = J.valuePtr();
  std::vector<double> Jb, y, Hb;
  std::vector<Eigen::Vector3d> p;
  const Term& t = constraints_;
  for (int b = 0; b < t.block_count(); ++b) {
    const int k = t.block_size(b), m = t.residual_count(b), cols = 3 * k;
    p.resize(k);
    Jb.resize(static_cast<size_t>(m) * cols);
    gather_block(t, b, x, p.data());
    t.evaluate(b, p.data(), c.data() + first_row_[b], Jb.data());
    for (int i = 0; i < m; ++i) {
      double* row = values + J.outerIndexPtr()[first_row_[b] + i];
      for (int j = 0; j < k; ++j)
        for (int e = 0; e < 3; ++e) row[3 * column_rank_[b][j] + e] = Jb[i * cols + 3 * j + e];
    }
    if (!hessian) continue;
    const int* v = t.block_vertices(b);
    G_.add_gram(v, k, Jb.data(), m, 1.0);
    if (!options_.lagrangian_hessian && !polishing_) continue;
    y.resize(m);
    for (int i = 0; i < m; ++i) y[i] = -lambda_[first_row_[b] + i];
    Hb.assign(static_cast<size_t>(cols) * cols, 0.0);
    t.add_second_order(b, p.data(), y.data(), Hb.data());
    H_.add_dense(v, k, Hb.data(), 1.0);
  }
}

SqpSolver::Linearization SqpSolver::linearization(const Dofs& x, double rho, Eigen::SparseMatrix<double>* K) {
  Linearization lin;
  linearize(x, lin, K != nullptr);
  if (K) {
    *K = H_.lower();
    *K += rho * G_.lower();
  }
  return lin;
}

bool SqpSolver::refactorize(const Dofs& x, Linearization& lin, double epsilon, SqpReport& report) {
  const auto t_asm = Clock::now();
  linearize(x, lin, true);
  report.assembly_ms += ms_since(t_asm);
  factored_ = false;
  if (!H_.lower().coeffs().allFinite() || !G_.lower().coeffs().allFinite()) return false;
  factored_J_ = lin.J;
  const auto t0 = Clock::now();
  // K = H + rho J^T J must be positive definite. Where it is not, H is indefinite across the
  // constraints (only with lagrangian_hessian): raise rho up to rho_max first, then the shift.
  rho_ = 1 / epsilon;
  auto assemble = [&]() {
    const double* h = H_.lower().valuePtr();
    const double* g = G_.lower().valuePtr();
    double* k = K_.mutable_values();
    for (Eigen::Index i = 0; i < K_.lower().nonZeros(); ++i) k[i] = h[i] + rho_ * g[i];
  };
  assemble();
  for (int attempt = 0; attempt < 24; ++attempt) {
    llt_->setShift(delta_);
    llt_->factorize(K_.lower());
    if (llt_->info() == Eigen::Success) {
      ++report.factorizations;
      report.factor_ms += ms_since(t0);
      factored_ = true;
      return true;
    }
    if (rho_ < rho_cap_) {
      rho_ = std::min(10 * rho_, rho_cap_);
      assemble();
    } else {
      delta_ = std::max(10 * delta_, 1e-8);
    }
  }
  report.factor_ms += ms_since(t0);
  return false;
}

Eigen::VectorXd SqpSolver::solve(const Eigen::VectorXd& rhs, SqpReport& report) const {
  const auto t0 = Clock::now();
  Eigen::VectorXd d = llt_->solve(rhs);
  report.factor_ms += ms_since(t0);
  return d;
}

SqpReport SqpSolver::iterate(Dofs& x, bool last) {
  SqpReport report = solve_iteration(x, false);
  if (!last || report.failed || report.constraint_max <= options_.final_constraint_tolerance) return report;
  // The last iteration of a run polishes the state to the final tolerance. How far rho may grow
  // to keep K positive definite with the constraints' curvature decides which states a polish
  // reaches (measured: neither 1e10 nor 1e12 suits every thesis case), so it tries rho up to
  // rho_max / 100 first, then up to rho_max, each from the unpolished state. A polish that fails
  // or ends less feasible is dropped.
  const Dofs x1 = x;
  const Eigen::VectorXd lambda1 = lambda_;
  Dofs best_x = x1;
  Eigen::VectorXd best_lambda = lambda1;
  for (const double cap : {options_.rho_max / 100, options_.rho_max}) {
    if (report.constraint_max <= options_.final_constraint_tolerance) break;
    rho_cap_ = std::max(cap, 1 / options_.epsilon);
    x = x1;
    lambda_ = lambda1;
    const SqpReport polish = solve_iteration(x, true);
    rho_cap_ = options_.rho_max;
    add_work(report, polish);
    if (!polish.failed && polish.constraint_max < report.constraint_max) {
      best_x = x;
      best_lambda = lambda_;
      report.constraint_max = polish.constraint_max;
      if (polish.steps > 0) report.step_length = polish.step_length;
    }
  }
  x = best_x;
  lambda_ = best_lambda;
  factored_ = false;
  if (report.constraint_max > options_.final_constraint_tolerance) {
    // The polish stopped short (4_corners 81x81: 4.6e-6 after it): the projection's many small
    // steps finish it (to 3.2e-7 there).
    const SqpReport projection = project(x);
    add_work(report, projection);
    if (!projection.failed) report.constraint_max = projection.constraint_max;
  }
  return report;
}

SqpReport SqpSolver::solve_iteration(Dofs& x, bool last) {
  SqpReport report;
  const Dofs x0 = x;
  const Eigen::VectorXd lambda0 = lambda_;
  auto fail = [&](const std::string& why) {
    x = x0;
    lambda_ = lambda0;
    factored_ = false;
    report.failed = true;
    report.failure = why;
    return report;
  };
  auto relinearize = [&](Linearization& lin) {
    const auto t = Clock::now();
    linearize(x, lin, false);
    report.assembly_ms += ms_since(t);
    return std::isfinite(lin.f) && lin.g.allFinite() && lin.c.allFinite();
  };
  const char* not_finite = "the objective or the DOG constraints are not finite (NaN or infinity)";
  delta_ = options_.regularization;

  Linearization lin;
  if (!relinearize(lin)) return fail(not_finite);
  double error = kkt_error(lin) * 1e4;  // as in the reference: at least one step unless tiny
  // Polishing: exact-Hessian SQP steps (the multipliers are settled by then) until the
  // constraints meet the final tolerance.
  polishing_ = last;
  const ClearOnExit unset{polishing_};
  const int max_steps = last ? std::max(options_.max_steps, options_.polish_steps) : options_.max_steps;
  auto more_steps = [&]() {
    if (report.steps >= max_steps) return false;
    if (last) return error > options_.kkt_tolerance && lin.c.lpNorm<Eigen::Infinity>() > options_.final_constraint_tolerance;
    return error > options_.kkt_tolerance;
  };
  while (more_steps()) {
    if (!refactorize(x, lin, options_.epsilon, report))
      return fail("the Cholesky factorisation failed (non-finite Hessian, or not positive definite even with rho " +
                  format_number(rho_) + " and shift " + format_number(delta_) + ")");
    const Eigen::VectorXd Jtc = lin.J.transpose() * lin.c;
    const Eigen::VectorXd grad_phi = lin.g - lin.J.transpose() * lambda_ + rho_ * Jtc;
    const Eigen::VectorXd d = solve(-grad_phi, report);
    const Eigen::VectorXd lambda_plus = lambda_ - rho_ * (lin.J * d + lin.c);
    if (!d.allFinite() || !lambda_plus.allFinite()) return fail("the KKT solve produced NaN or infinity");

    // Backtracking with the Armijo condition on Phi_mu (see the header).
    double alpha = 1, phi0 = 0, slope = 0;
    Dofs x_try;
    auto search = [&](double mu, int max_halvings) {
      phi0 = lin.f - lambda_.dot(lin.c) + 0.5 * mu * lin.c.squaredNorm();
      slope = (grad_phi + (mu - rho_) * Jtc).dot(d);
      auto sufficient = [&](double phi, double a) {
        return std::isfinite(phi) && phi <= phi0 + options_.armijo * a * slope;
      };
      alpha = 1;
      for (int k = 0; k <= max_halvings && slope < 0; ++k, alpha *= 0.5) {
        x_try = x + alpha * d;
        if (sufficient(augmented_lagrangian(x_try, mu), alpha)) return true;
        if (k == 0 && options_.second_order_correction) {
          const Dofs x_soc = x_try + solve(-rho_ * (lin.J.transpose() * constraint_values(x_try)), report);
          if (sufficient(augmented_lagrangian(x_soc, mu), 1.0)) {
            x_try = x_soc;
            return true;
          }
        }
      }
      return false;
    };
    const double mu = std::min(options_.merit_penalty, rho_);
    const bool accepted = search(rho_, mu < rho_ ? options_.trusted_backtracks : options_.max_backtracks) ||
                          (mu < rho_ && search(mu, options_.max_backtracks));
    if (!accepted) {
      // A direction that cannot decrease Phi even by the rounding of its value: already
      // stationary (this happens once a held run has converged).
      if (-slope <= 1e-12 * (1 + std::abs(phi0))) break;
      return fail("the line search found no decrease of the merit function (directional derivative " +
                  format_number(slope) + ")");
    }
    x = x_try;
    lambda_ += alpha * (lambda_plus - lambda_);
    report.step_length = alpha;
    ++report.steps;
    if (report.steps < max_steps) {
      if (!relinearize(lin)) return fail(not_finite);
      error = kkt_error(lin);
    } else {
      lin.c = constraint_values(x);  // all the restoration needs
    }
  }

  const double tolerance = last ? options_.final_constraint_tolerance : options_.constraint_tolerance;
  const int max_restoration = last ? 2 * options_.max_restoration_steps : options_.max_restoration_steps;
  Eigen::VectorXd c = lin.c;
  if (!c.allFinite()) return fail(not_finite);
  if (!restore(x, c, tolerance, max_restoration, true, report)) return fail(report.failure);
  report.constraint_max = c.lpNorm<Eigen::Infinity>();
  return report;
}

SqpReport SqpSolver::restore_constraints(Dofs& x) {
  SqpReport report;
  factored_ = false;  // the factor of an earlier state does not fit x
  Eigen::VectorXd c = constraint_values(x);
  if (!c.allFinite() || !restore(x, c, options_.constraint_tolerance, options_.max_restoration_steps, true, report)) {
    report.failed = true;
    if (report.failure.empty()) report.failure = "the DOG constraints are not finite";
  }
  return report;
}

SqpReport SqpSolver::project(Dofs& x) {
  SqpReport report;
  factored_ = false;  // the factor of an earlier state does not fit x
  polishing_ = true;  // the polishing metric in restore()
  const ClearOnExit unset{polishing_};
  const Dofs x0 = x;
  Eigen::VectorXd c = constraint_values(x);
  // First without local steps: they move the few vertices around the violated rows with the rest
  // frozen, and from 1.2e-5 (4_corners 41x41, twolevel then standard from iteration 281) they
  // stalled at 1.2e-6 where chord and global steps reach 3.6e-7. Then, if that stops short, with
  // them: the standard's 1_curve 81x59 stalled at 3.6e-6 without them.
  const double tolerance = options_.final_constraint_tolerance;
  bool ok = c.allFinite() && restore(x, c, tolerance, kProjectionSteps, false, report);
  if (ok && c.lpNorm<Eigen::Infinity>() > tolerance)
    ok = restore(x, c, tolerance, report.restoration_steps + kProjectionSteps, true, report);
  if (!ok) {
    x = x0;
    report.failed = true;
    if (report.failure.empty()) report.failure = "the DOG constraints are not finite";
    return report;
  }
  report.constraint_max = c.lpNorm<Eigen::Infinity>();
  return report;
}

bool SqpSolver::restore(Dofs& x, Eigen::VectorXd& c, double tolerance, int max_steps, bool local_steps,
                        SqpReport& report) {
  enum Kind { kChord, kLocal, kGlobal };
  // Polishing restores with a weaker metric term: H then barely resists the last, small corrections.
  const double epsilon = polishing_ ? options_.polish_epsilon : options_.restoration_epsilon;
  bool chord_ok = factored_, local_ok = local_steps;
  int chords = 0;
  double cmax = c.lpNorm<Eigen::Infinity>();
  Linearization lin;
  Eigen::VectorXd c_try;
  while (cmax > tolerance && report.restoration_steps < max_steps) {
    const int violated = static_cast<int>((c.array().abs() > tolerance).count());
    const Kind kind = chord_ok                                                   ? kChord
                      : local_ok && violated <= options_.local_fraction * rows_ ? kLocal
                                                                                 : kGlobal;
    Eigen::VectorXd d;
    if (kind == kChord) {
      d = solve(-rho_ * (factored_J_.transpose() * c), report);
    } else if (kind == kLocal) {
      const auto t0 = Clock::now();
      RowMatrix J;
      fill_constraints(x, c, J, false);
      const bool ok = local_.step(local_.neighbourhood(c, tolerance), c, J, H_.lower(),
                                  1 / epsilon, options_.regularization, d);
      report.factor_ms += ms_since(t0);
      if (!ok) {
        local_ok = false;
        continue;
      }
    } else {
      // Restoration is Gauss-Newton on |c|^2: its metric is the objective's Hessian without the
      // constraints' (indefinite) curvature, also when polishing.
      const bool polishing = polishing_;
      polishing_ = false;
      const bool factored = refactorize(x, lin, epsilon, report);
      polishing_ = polishing;
      // The state is still valid (finite): restoration ends and the residual left is reported in
      // the diagnostics (and the run's warning), as when |c| cannot be reduced further.
      if (!factored) break;
      d = solve(-rho_ * (lin.J.transpose() * lin.c), report);
    }
    if (!d.allFinite()) {
      report.failure = "a restoration step produced NaN or infinity";
      return false;
    }
    const double c0 = c.squaredNorm();
    double alpha = 1, c1 = c0;
    for (int k = 0; k <= options_.max_backtracks; ++k, alpha *= 0.5) {
      c_try = constraint_values(x + alpha * d);
      c1 = c_try.squaredNorm();
      if (c1 < c0) break;
    }
    if (!(c1 < c0)) {  // also false for NaN
      if (kind == kChord) chord_ok = false;
      else if (kind == kLocal) local_ok = false;
      else break;  // |c| cannot be reduced further from here: reported as it is
      continue;
    }
    x += alpha * d;
    c = c_try;
    ++report.restoration_steps;
    if (kind == kLocal) ++report.local_steps;
    // Chord steps continue while they make progress; a fresh factorisation makes them possible again.
    if (kind == kChord) ++chords;
    chord_ok = (kind == kChord && c1 < kChordProgress * c0 && chords < kMaxChords) || kind == kGlobal;
    cmax = c.lpNorm<Eigen::Infinity>();
  }
  return true;
}

}  // namespace sdog
