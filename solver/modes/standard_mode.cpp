#include "solver/modes/standard_mode.h"

#include <algorithm>

#include "solver/sqp/blas_threads.h"

namespace sdog {

std::string StandardOptions::validate() const {
  if (const std::string m = sqp.validate(); !m.empty()) return m;
  if (!(max_fold_bias > 0)) return "max_fold_bias must be positive";
  if (blas_threads < 0) return "blas_threads must be >= 0";
  return "";
}

StandardMode::StandardMode(DogProblem& problem, const Scenario& scenario, const StandardOptions& options)
    : problem_(problem), scenario_(scenario), options_(options), base_fold_bias_(problem.weights.fold_bias) {
  scenario_.install(problem_);
  if (!scenario.keeps_folds) options_.folding = false;
  if (!options_.folding) problem_.weights.fold_bias = 0;
  sqp_ = std::make_unique<SqpSolver>(problem_.mesh().vertex_count(), problem_.objective_terms(), problem_.dog,
                                     options_.sqp);
}

void StandardMode::set_time(double t) { scenario_.apply(problem_, t); }

StepReport StandardMode::iterate(Dofs& x, bool last) {
  // Every iteration: a patch mode before may have lowered it.
  set_blas_threads(options_.blas_threads > 0 ? options_.blas_threads : default_blas_threads());
  StepReport report;
  double constraint_max = 0;  // of the last attempt
  auto run = [&]() {
    const SqpReport r = sqp_->iterate(x, last);
    report.sqp_steps += r.steps;
    report.factorizations += r.factorizations;
    report.restoration_steps += r.restoration_steps;
    report.step_length = r.step_length;
    constraint_max = r.constraint_max;
    report.factor_ms += r.factor_ms;
    report.failed = r.failed;
    report.failure = r.failure;
    return !r.failed;
  };
  if (!options_.folding) {
    run();
    return report;
  }
  const Dofs x0 = x;
  const Eigen::VectorXd lambda0 = sqp_->multipliers();
  if (!run()) return report;
  FoldCheck check = check_folded(problem_.mesh(), problem_.sites, x);
  report.folded = check.folded;
  if (report.folded) {
    set_fold_bias(base_fold_bias_);
    return report;
  }
  // The attempt with the fewest unfolded sites so far (the lowest weight among equals) whose
  // constraints are as well met as the first attempt's (or to the solver's tolerance): what the
  // iteration keeps when no escalation folds the sheet.
  const double feasible = std::max(constraint_max, options_.sqp.constraint_tolerance);
  struct Attempt {
    Dofs x;
    Eigen::VectorXd lambda;
    int violations;
    double step_length;
  } best{x, sqp_->multipliers(), check.violations, report.step_length};
  // As in the reference: an escalated bias stays for the next iteration and returns to its base
  // value once an iteration ends folded.
  double weight = problem_.weights.fold_bias;
  while (!report.folded && weight > 0 && weight * 10 <= options_.max_fold_bias) {
    x = x0;
    sqp_->set_multipliers(lambda0);
    set_fold_bias(weight *= 10);
    ++report.fold_retries;
    if (!run()) {  // a retry the solver cannot take ends the escalation; the best attempt stands
      report.failed = false;
      report.failure.clear();
      break;
    }
    check = check_folded(problem_.mesh(), problem_.sites, x);
    report.folded = check.folded;
    if (check.violations < best.violations && constraint_max <= feasible) best = {x, sqp_->multipliers(), check.violations, report.step_length};
  }
  if (!report.folded && report.fold_retries > 0) {
    // Unlike the reference, which kept the last attempt and the capped weight: past a point the
    // bias only wrecks the DOG constraints (a residual of 2 was seen at 1e14) without folding.
    x = best.x;
    sqp_->set_multipliers(best.lambda);
    report.step_length = best.step_length;
    set_fold_bias(base_fold_bias_);
  }
  return report;
}

void StandardMode::start_from(const Dofs&) {
  sqp_->set_multipliers(Eigen::VectorXd::Zero(sqp_->multipliers().size()));
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
