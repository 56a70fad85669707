#include "solver/sqp/sqp_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/sqp/cholmod_factor.h"

namespace sdog {
namespace {

// The first KKT error of a pass counts this many times, so that at least one step runs unless the
// error is tiny (as in the reference).
constexpr double kFirstErrorWeight = 1e4;
// A converging iteration's passes that do not lower the lowest objective by more than its
// resolution, in a row, before the state counts as converged.
constexpr int kPassesWithoutProgress = 3;
// The polish tries rho capped at rho_max / this first, then at rho_max.
constexpr double kFirstPolishCapDivisor = 100;
// In a converging iteration, a restoration that stops short multiplies the next pass's
// restoration_epsilon by this; one that takes less than half its steps divides it by this (up to
// the option's value).
constexpr double kRestorationEpsilonFactor = 0.1;
const char* const kNotFinite =
    "the objective or the DOG constraints are not finite (NaN or infinity)";

std::vector<const Term*> all_terms(const std::vector<WeightedTerm>& objective,
                                   const Term& constraints) {
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
      m_{SymmetricBlockMatrix(vertex_count, all_terms(objective_, constraints)),
         SymmetricBlockMatrix(vertex_count, all_terms(objective_, constraints)),
         SymmetricBlockMatrix(vertex_count, all_terms(objective_, constraints)),
         SymmetricBlockMatrix(vertex_count, all_terms(objective_, constraints))},
      local_(vertex_count, constraints, options.local_rings),
      factorization_stop_(std::numeric_limits<long>::max()) {
  for (int b = 0; b < constraints_.block_count(); ++b) {
    rows_.first.push_back(rows_.count);
    rows_.count += constraints_.residual_count(b);
  }
  lambda_ = Eigen::VectorXd::Zero(rows_.count);
  delta_ = options_.regularization;
  std::vector<Eigen::Triplet<double>> entries;
  rows_.column_rank.resize(constraints_.block_count());
  for (int b = 0; b < constraints_.block_count(); ++b) {
    const int k = constraints_.block_size(b);
    const int* v = constraints_.block_vertices(b);
    for (int j = 0; j < k; ++j)
      rows_.column_rank[b].push_back(
          static_cast<int>(std::count_if(v, v + k, [&](int u) { return u < v[j]; })));
    for (int i = 0; i < constraints_.residual_count(b); ++i)
      for (int j = 0; j < k; ++j)
        for (int e = 0; e < 3; ++e) entries.emplace_back(rows_.first[b] + i, 3 * v[j] + e, 1.0);
  }
  rows_.pattern.resize(rows_.count, 3 * n_);
  rows_.pattern.setFromTriplets(entries.begin(), entries.end());
  rows_.pattern.makeCompressed();
  factor_ = std::make_unique<CholmodFactor>(m_.K.lower());
}

SqpSolver::~SqpSolver() = default;

SqpSolver::Pass SqpSolver::ordinary_pass() const {
  return {std::max(options_.constraint_tolerance, restoration_tolerance_),
          options_.max_steps,
          options_.max_restoration_steps,
          false,
          options_.lagrangian_hessian,
          options_.restoration_epsilon,
          options_.rho_max,
          true,
          options_.trusted_backtracks};
}

SqpSolver::Pass SqpSolver::polish_pass(double rho_cap) const {
  return {options_.final_constraint_tolerance,
          std::max(options_.max_steps, options_.polish_steps),
          2 * options_.max_restoration_steps,
          true,
          true,
          options_.polish_epsilon,
          std::max(rho_cap, 1 / options_.epsilon),
          true,
          options_.trusted_backtracks};
}

SqpReport SqpSolver::iterate(Dofs& x, bool last) {
  SqpReport report = run_pass(x, ordinary_pass());
  if (last && !report.failed && report.constraint_max > options_.final_constraint_tolerance)
    polish(x, report);
  return report;
}

void SqpSolver::adapt_restoration(Pass& pass, const SqpReport& r) const {
  // A restoration that stops short of its tolerance (where creases cross, the objective's
  // Hessian outweighs rho J^T J in the directions the constraints need, and the steps crawl)
  // goes on in a metric closer to Gauss-Newton on |c|^2 alone in the next pass; one that needs
  // few steps goes back towards restoration_epsilon (a larger rho costs failed factorizations).
  if (r.constraint_max > pass.tolerance)
    pass.restoration_epsilon =
        std::max(kRestorationEpsilonFactor * pass.restoration_epsilon,
                 std::min(options_.polish_epsilon, options_.restoration_epsilon));
  else if (2 * r.work.restoration_steps < pass.max_restoration_steps)
    pass.restoration_epsilon = std::min(pass.restoration_epsilon / kRestorationEpsilonFactor,
                                        options_.restoration_epsilon);
}

SqpReport SqpSolver::converge(Dofs& x, int max_steps) {
  // Passes of one optimality step and its restoration, as in iterate() but without the forced
  // first step, until a full step would lower f by at most converged_decrease (to first order).
  // The objective's change of a step does not serve: the line search shortens steps near a fold.
  // The line search tries the full step with the penalty rho, then goes on with merit_penalty at
  // once: steps towards targets that moved far violate the constraints through their curvature,
  // which rho punishes far more than the objective gains, and restoration removes that violation.
  Pass pass = ordinary_pass();
  pass.max_steps = 1;
  pass.first_step_always = false;
  pass.trusted_backtracks = 0;
  SqpReport report;
  double f_before = objective(x), f_best = f_before;
  int still_passes = 0, without_progress = 0;
  report.constraint_max = constraint_values(x).lpNorm<Eigen::Infinity>();
  const bool feasible_start = report.constraint_max <= options_.constraint_tolerance;
  while (true) {
    const Dofs x_pass = x;
    const Eigen::VectorXd lambda_pass = lambda_;
    const SqpReport r = run_pass(x, pass);
    report.work += r.work;
    if (r.failed) {                    // run_pass took x and the multipliers back to x_pass
      if (!std::isfinite(f_before)) {  // targets or state not finite: no step can help
        report.failed = true;
        report.failure = r.failure;
        return report;
      }
      ++report.work.recovered_failures;
      if (pass.max_step <= kSmallestPassStep) break;
      pass.max_step /= 2;
      pass.restoration_epsilon = options_.restoration_epsilon;
      continue;
    }
    adapt_restoration(pass, r);
    // From a feasible state, a pass that ends feasible but higher went too far along the
    // linearised constraints (its restoration took back more than its step gained): it is taken
    // back, and the next one is shorter.
    const double f = objective(x), resolution = options_.converged_decrease * std::max(1.0, f);
    const bool rejected = feasible_start && r.work.steps > 0 &&
                          r.constraint_max <= options_.constraint_tolerance && f > f_before;
    if (rejected) {
      x = x_pass;
      lambda_ = lambda_pass;
      pass.max_step /= 2;
    } else {
      if (r.work.steps > 0) {
        pass.max_step = std::min(1.0, 2 * pass.max_step);
        report.step_length = r.step_length;
      }
      report.constraint_max = r.constraint_max;
    }
    const double f_now = rejected ? f_before : f;
    // Stationary: a full step would gain next to nothing; or the steps no longer change f (two
    // passes in a row: the line search and the restoration undo each other, a cycle the first
    // test does not see, which rounding alone can start or avoid); or kPassesWithoutProgress
    // passes have not lowered the lowest f by more than the resolution (restoration to the
    // constraint tolerance moves f by more than that where the constraints pull hard, as on a
    // sheet folded towards angles it cannot reach).
    still_passes = !rejected && std::abs(f - f_before) <= resolution ? still_passes + 1 : 0;
    without_progress = f_now < f_best - resolution ? 0 : without_progress + 1;
    f_best = std::min(f_best, f_now);
    f_before = f_now;
    const bool stationary = r.work.steps == 0 ||
                            (!rejected && std::abs(r.full_step_decrease) <= resolution) ||
                            still_passes >= 2 || without_progress >= kPassesWithoutProgress;
    report.converged = stationary && report.constraint_max <= options_.constraint_tolerance;
    // A pass without a step (stationary) would repeat itself.
    if (report.converged || r.work.steps == 0 || report.work.steps >= max_steps) break;
  }
  return report;
}

// The last iteration of a run polishes the state to the final tolerance. How far rho may grow to
// keep K positive definite with the constraints' curvature decides which states a polish reaches
// (no one cap suits every thesis case), so it tries a low cap first, then rho_max, each from the
// unpolished state, and keeps the more feasible result. A polish that fails or ends less feasible
// is dropped; one that stops short is finished by the projection.
void SqpSolver::polish(Dofs& x, SqpReport& report) {
  const LastIterationBudget budget(*this);
  const Dofs x1 = x;
  const Eigen::VectorXd lambda1 = lambda_;
  Dofs best_x = x1;
  Eigen::VectorXd best_lambda = lambda1;
  for (const double cap : {options_.rho_max / kFirstPolishCapDivisor, options_.rho_max}) {
    if (report.constraint_max <= options_.final_constraint_tolerance) break;
    x = x1;
    lambda_ = lambda1;
    const SqpReport polished = run_pass(x, polish_pass(cap));
    report.work += polished.work;
    if (!polished.failed && polished.constraint_max < report.constraint_max) {
      best_x = x;
      best_lambda = lambda_;
      report.constraint_max = polished.constraint_max;
      if (polished.work.steps > 0) report.step_length = polished.step_length;
    }
  }
  x = best_x;
  lambda_ = best_lambda;
  factored_ = false;
  if (report.constraint_max > options_.final_constraint_tolerance) {
    const SqpReport projection = project(x);
    report.work += projection.work;
    if (!projection.failed) report.constraint_max = projection.constraint_max;
  }
}

SqpSolver::LastIterationBudget::LastIterationBudget(SqpSolver& solver)
    : solver_(solver),
      owner_(solver.factorization_stop_ == std::numeric_limits<long>::max() &&
             solver.options_.polish_factorizations > 0) {
  if (owner_)
    solver_.factorization_stop_ = solver_.factorizations_ + solver_.options_.polish_factorizations;
}

SqpSolver::LastIterationBudget::~LastIterationBudget() {
  if (owner_) solver_.factorization_stop_ = std::numeric_limits<long>::max();
}

SqpReport SqpSolver::run_pass(Dofs& x, const Pass& pass) {
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
  delta_ = options_.regularization;
  Linearization lin;
  if (!relinearize(x, lin, report)) return fail(kNotFinite);
  double error = kkt_error(lin) * (pass.first_step_always ? kFirstErrorWeight : 1);
  auto more_steps = [&]() {
    if (report.work.steps >= pass.max_steps || !(error > options_.kkt_tolerance) ||
        !within_budget())
      return false;
    return !pass.stop_when_feasible || lin.c.lpNorm<Eigen::Infinity>() > pass.tolerance;
  };
  while (more_steps()) {
    const StepOutcome outcome = optimality_step(x, lin, pass, report);
    if (outcome == StepOutcome::kFailed) return fail(report.failure);
    if (outcome == StepOutcome::kStationary) break;
    if (report.work.steps < pass.max_steps) {
      if (!relinearize(x, lin, report)) return fail(kNotFinite);
      error = kkt_error(lin);
    } else {
      lin.c = constraint_values(x);  // all the restoration needs
    }
  }
  Eigen::VectorXd c = lin.c;
  if (!c.allFinite()) return fail(kNotFinite);
  const Restoration restoration{pass.tolerance, pass.max_restoration_steps, local_fraction(),
                                pass.restoration_epsilon, pass.rho_cap};
  if (!restore(x, c, restoration, report)) return fail(report.failure);
  report.constraint_max = c.lpNorm<Eigen::Infinity>();
  return report;
}

}  // namespace sdog
