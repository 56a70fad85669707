// Restoration of the DOG constraints (sqp_solver.h, step 2) and the projection that ends a run.
#include <algorithm>

#include "base/stopwatch.h"
#include "solver/sqp/sqp_solver.h"

namespace sdog {
namespace {

// A chord restoration step is followed by another while it cuts |c|^2 at least this much, up to
// kMaxChords in a row.
constexpr double kChordProgress = 0.8;
constexpr int kMaxChords = 5;
constexpr double kBacktrack = 0.5;
const char* const kConstraintsNotFinite = "the DOG constraints are not finite";

}  // namespace

SqpReport SqpSolver::restore_constraints(Dofs& x) {
  SqpReport report;
  factored_ = false;  // the factor of an earlier state does not fit x
  Eigen::VectorXd c = constraint_values(x);
  const Restoration restoration{options_.constraint_tolerance, options_.max_restoration_steps,
                                local_fraction(), options_.restoration_epsilon, options_.rho_max};
  if (!c.allFinite() || !restore(x, c, restoration, report)) {
    report.failed = true;
    if (report.failure.empty()) report.failure = kConstraintsNotFinite;
  }
  report.constraint_max = c.lpNorm<Eigen::Infinity>();
  return report;
}

SqpReport SqpSolver::project(Dofs& x) {
  const LastIterationBudget budget(*this);
  SqpReport report;
  factored_ = false;  // the factor of an earlier state does not fit x
  const Dofs x0 = x;
  Eigen::VectorXd c = constraint_values(x);
  // First without local steps: they move the few vertices around the violated rows with the rest
  // frozen and can stall above the tolerance where chord and global steps reach it. Then, if that
  // stops short, with them, which finish the cases where the global steps stall.
  Restoration restoration{options_.final_constraint_tolerance, options_.projection_steps, 0,
                          options_.polish_epsilon, options_.rho_max};
  bool ok = c.allFinite() && restore(x, c, restoration, report);
  if (ok && c.lpNorm<Eigen::Infinity>() > restoration.tolerance) {
    restoration.max_steps = report.work.restoration_steps + options_.projection_steps;
    restoration.local_fraction = std::max(local_fraction(), SqpOptions::kDefaultLocalFraction);
    ok = restore(x, c, restoration, report);
  }
  if (!ok) {
    x = x0;
    report.failed = true;
    if (report.failure.empty()) report.failure = kConstraintsNotFinite;
    return report;
  }
  report.constraint_max = c.lpNorm<Eigen::Infinity>();
  return report;
}

bool SqpSolver::restore(Dofs& x, Eigen::VectorXd& c, const Restoration& settings,
                        SqpReport& report) {
  enum Kind { kChord, kLocal, kGlobal };
  bool chord_ok = factored_, local_ok = settings.local_fraction > 0;
  int chords = 0;
  const double tolerance = settings.tolerance;
  double cmax = c.lpNorm<Eigen::Infinity>();
  Linearization lin;
  Eigen::VectorXd c_try;
  while (cmax > tolerance && report.work.restoration_steps < settings.max_steps &&
         within_budget()) {
    const int violated = static_cast<int>((c.array().abs() > tolerance).count());
    const Kind kind = chord_ok                                                        ? kChord
                      : local_ok && violated <= settings.local_fraction * rows_.count ? kLocal
                                                                                      : kGlobal;
    Eigen::VectorXd d;
    if (kind == kChord) {
      d = solve(-rho_ * (factored_J_.transpose() * c), report);
    } else if (kind == kLocal) {
      const auto t0 = Clock::now();
      RowMatrix J;
      fill_constraints(x, c, J, false, false);
      const bool ok = local_.step(local_.neighbourhood(c, tolerance), c, J, m_.H.lower(),
                                  1 / settings.epsilon, options_.regularization, d);
      report.work.factor_ms += ms_since(t0);
      if (!ok) {
        local_ok = false;
        continue;
      }
    } else {
      // Restoration is Gauss-Newton on |c|^2: its metric is the objective's Hessian without the
      // constraints' (indefinite) curvature, also in the polish.
      // The state is still valid (finite) when the factorisation fails: restoration ends and the
      // residual left is reported in the diagnostics (and the run's warning), as when |c| cannot
      // be reduced further.
      if (!refactorize(x, lin, settings.epsilon, options_.lagrangian_hessian, settings.rho_cap,
                       report))
        break;
      d = solve(-rho_ * (lin.J.transpose() * lin.c), report);
    }
    if (!d.allFinite()) {
      report.failure = "a restoration step produced NaN or infinity";
      return false;
    }
    const double c0 = c.squaredNorm();
    double alpha = 1, c1 = c0;
    for (int k = 0; k <= options_.max_backtracks; ++k, alpha *= kBacktrack) {
      c_try = constraint_values(x + alpha * d);
      c1 = c_try.squaredNorm();
      if (c1 < c0) break;
    }
    if (!(c1 < c0)) {  // also false for NaN
      if (kind == kChord)
        chord_ok = false;
      else if (kind == kLocal)
        local_ok = false;
      else
        break;  // |c| cannot be reduced further from here: reported as it is
      continue;
    }
    x += alpha * d;
    c = c_try;
    ++report.work.restoration_steps;
    if (kind == kLocal) ++report.work.local_steps;
    // Chord steps continue while they make progress; a fresh factorisation makes them possible
    // again.
    if (kind == kChord) ++chords;
    chord_ok =
        (kind == kChord && c1 < kChordProgress * c0 && chords < kMaxChords) || kind == kGlobal;
    cmax = c.lpNorm<Eigen::Infinity>();
  }
  return true;
}

}  // namespace sdog
