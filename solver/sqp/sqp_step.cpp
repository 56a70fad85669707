// One optimality step of the SQP solver: the regularised KKT system solved through K, then a
// backtracking line search on the augmented Lagrangian (sqp_solver.h, step 1).
#include <cmath>

#include "base/text_format.h"
#include "solver/sqp/sqp_solver.h"

namespace sdog {
namespace {

// A search direction whose slope is this small relative to Phi cannot decrease Phi even by the
// rounding of its value: the state is already stationary (a held run that has converged).
constexpr double kStationarySlope = 1e-12;
// Line-search step halving.
constexpr double kBacktrack = 0.5;

}  // namespace

SqpSolver::StepOutcome SqpSolver::optimality_step(Dofs& x, Linearization& lin, const Pass& pass,
                                                  SqpReport& report) {
  if (!refactorize(x, lin, options_.epsilon, pass.curvature, pass.rho_cap, report)) {
    report.failure =
        !m_.H.lower().coeffs().allFinite() || !m_.G.lower().coeffs().allFinite()
            ? "the Hessian is not finite (NaN or infinity)"
            : "the Cholesky factorisation failed (not positive definite even with rho " +
                  format_number(rho_) + " and shift " + format_number(delta_) + ")";
    return StepOutcome::kFailed;
  }
  const Eigen::VectorXd Jtc = lin.J.transpose() * lin.c;
  const Eigen::VectorXd grad_phi = lin.g - lin.J.transpose() * lambda_ + rho_ * Jtc;
  const Eigen::VectorXd d = solve(-grad_phi, report);
  const Eigen::VectorXd lambda_plus = lambda_ - rho_ * (lin.J * d + lin.c);
  if (!d.allFinite() || !lambda_plus.allFinite()) {
    report.failure = "the KKT solve produced NaN or infinity";
    return StepOutcome::kFailed;
  }
  // First with mu = rho, for which d is a Newton direction; if that needs more than
  // trusted_backtracks halvings, again with the smaller merit_penalty (sqp_solver.h).
  const double mu = std::min(options_.merit_penalty, rho_);
  LineSearch search = line_search(x, lin, d, grad_phi, Jtc, rho_,
                                  mu < rho_ ? pass.trusted_backtracks : options_.max_backtracks,
                                  pass.max_step, report);
  if (!search.accepted && mu < rho_)
    search =
        line_search(x, lin, d, grad_phi, Jtc, mu, options_.max_backtracks, pass.max_step, report);
  if (!search.accepted) {
    if (-search.slope <= kStationarySlope * (1 + std::abs(search.phi0)))
      return StepOutcome::kStationary;
    report.failure =
        "the line search found no decrease of the merit function (directional derivative " +
        format_number(search.slope) + ")";
    return StepOutcome::kFailed;
  }
  report.full_step_decrease = -lin.g.dot(d);
  x = search.x;
  lambda_ += search.alpha * (lambda_plus - lambda_);
  report.step_length = search.alpha;
  ++report.work.steps;
  return StepOutcome::kTaken;
}

SqpSolver::LineSearch SqpSolver::line_search(const Dofs& x, const Linearization& lin,
                                             const Eigen::VectorXd& d,
                                             const Eigen::VectorXd& grad_phi,
                                             const Eigen::VectorXd& Jtc, double mu,
                                             int max_halvings, double max_step,
                                             SqpReport& report) const {
  LineSearch s;
  s.alpha = max_step;
  s.phi0 = lin.f - lambda_.dot(lin.c) + 0.5 * mu * lin.c.squaredNorm();
  s.slope = (grad_phi + (mu - rho_) * Jtc).dot(d);
  auto sufficient = [&](double phi, double a) {
    return std::isfinite(phi) && phi <= s.phi0 + options_.armijo * a * s.slope;
  };
  for (int k = 0; k <= max_halvings && s.slope < 0; ++k, s.alpha *= kBacktrack) {
    s.x = x + s.alpha * d;
    if (sufficient(augmented_lagrangian(s.x, mu), s.alpha)) {
      s.accepted = true;
      return s;
    }
    if (k == 0 && max_step == 1 && options_.second_order_correction) {
      // The full step pulled back onto c = 0 with the same factorisation.
      Dofs x_soc = s.x + solve(-rho_ * (lin.J.transpose() * constraint_values(s.x)), report);
      if (sufficient(augmented_lagrangian(x_soc, mu), 1.0)) {
        s.x = std::move(x_soc);
        s.accepted = true;
        return s;
      }
    }
  }
  return s;
}

}  // namespace sdog
