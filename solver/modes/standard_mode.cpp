#include "solver/modes/standard_mode.h"

#include <algorithm>

#include "solver/sqp/blas_threads.h"
#include "solver/sqp/sqp_solver.h"

namespace sdog {
namespace {

// Each retry multiplies the fold-bias weight by this.
constexpr double kFoldBiasGrowth = 10;

}  // namespace

StandardMode::StandardMode(DogProblem& problem, const Scenario& scenario, const StandardOptions& options)
    : problem_(problem),
      scenario_(scenario),
      options_(options),
      constraints_(problem, options.stitching),
      base_fold_bias_(problem.weights.fold_bias) {
  scenario_.install(problem_);
  if (!scenario.keeps_folds) options_.folding = false;
  if (!options_.folding) problem_.weights.fold_bias = 0;
  sqp_ = std::make_unique<SqpSolver>(problem_.mesh().vertex_count(), problem_.objective_terms(),
                                     constraints_.term(), options_.sqp);
}

StandardMode::~StandardMode() = default;

void StandardMode::set_time(double t) { scenario_.apply(problem_, t); }

StepReport StandardMode::iterate(const IterationContext& ctx, Dofs& x) {
  set_time(ctx.t);
  return step(x, ctx.last());
}

bool StandardMode::solve(Dofs& x, bool last, StepReport& report, double& constraint_max) {
  const SqpReport r = sqp_->iterate(x, last);
  report.work += r.work;
  report.step_length = r.step_length;
  constraint_max = r.constraint_max;
  report.failed = r.failed;
  report.failure = r.failure;
  return !r.failed;
}

StepReport StandardMode::step(Dofs& x, bool last) {
  // Every iteration: a patch mode before may have lowered it.
  set_blas_threads(options_.blas_threads > 0 ? options_.blas_threads : default_blas_threads());
  StepReport report;
  if (restore_first_) {
    restore_first_ = false;
    const SqpReport restored = sqp_->restore_constraints(x);
    report.work += restored.work;
    if (restored.failed) {
      report.failed = true;
      report.failure = restored.failure;
      return report;
    }
  }
  double constraint_max = 0;  // of the last attempt
  if (!options_.folding) {
    solve(x, last, report, constraint_max);
    return report;
  }
  const Dofs x0 = x;
  const Eigen::VectorXd lambda0 = sqp_->multipliers();
  if (!solve(x, last, report, constraint_max)) return report;
  const FoldCheck check = check_folded(problem_.mesh(), problem_.sites, x);
  report.folded = check.folded;
  if (report.folded) {
    set_fold_bias(base_fold_bias_);
    return report;
  }
  escalate_fold_bias(x, x0, lambda0, last, check.violations, constraint_max, report);
  return report;
}

void StandardMode::escalate_fold_bias(Dofs& x, const Dofs& x0, const Eigen::VectorXd& lambda0, bool last,
                                      int violations, double constraint_max, StepReport& report) {
  // The attempt with the fewest unfolded sites so far (the lowest weight among equals) whose
  // constraints are as well met as the first attempt's (or to the solver's tolerance): what the
  // iteration keeps when no escalation folds the sheet.
  const double feasible = std::max(constraint_max, options_.sqp.constraint_tolerance);
  struct Attempt {
    Dofs x;
    Eigen::VectorXd lambda;
    int violations;
    double step_length;
  } best{x, sqp_->multipliers(), violations, report.step_length};
  // As in the reference: an escalated bias stays for the next iteration and returns to its base
  // value once an iteration ends folded.
  double weight = problem_.weights.fold_bias;
  while (!report.folded && weight > 0 && weight * kFoldBiasGrowth <= options_.max_fold_bias) {
    x = x0;
    sqp_->set_multipliers(lambda0);
    set_fold_bias(weight *= kFoldBiasGrowth);
    ++report.work.fold_retries;
    if (!solve(x, last, report, constraint_max)) {  // a retry the solver cannot take ends the escalation
      report.failed = false;
      report.failure.clear();
      break;
    }
    const FoldCheck check = check_folded(problem_.mesh(), problem_.sites, x);
    report.folded = check.folded;
    if (check.violations < best.violations && constraint_max <= feasible)
      best = {x, sqp_->multipliers(), check.violations, report.step_length};
  }
  if (!report.folded && report.work.fold_retries > 0) {
    // Unlike the reference, which keeps the last attempt and the capped weight: past a point the
    // bias only wrecks the DOG constraints without folding (docs/design/rejected.md).
    x = best.x;
    sqp_->set_multipliers(best.lambda);
    report.step_length = best.step_length;
    set_fold_bias(base_fold_bias_);
  }
}

void StandardMode::start_from(const Dofs&) {
  sqp_->set_multipliers(Eigen::VectorXd::Zero(sqp_->multipliers().size()));
  restore_first_ = options_.stitching == Stitching::kExact;
  if (options_.folding) set_fold_bias(base_fold_bias_);
}

void StandardMode::set_folding(bool on) {
  options_.folding = on;
  set_fold_bias(on ? base_fold_bias_ : 0.0);
}

void StandardMode::set_fold_bias(double weight) {
  problem_.weights.fold_bias = weight;
  sqp_->set_weight(kFoldBias, weight);
}

}  // namespace sdog
