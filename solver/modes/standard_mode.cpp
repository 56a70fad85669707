#include "solver/modes/standard_mode.h"

#include <algorithm>

#include "solver/problem/diagnostics.h"
#include "solver/sqp/blas_threads.h"
#include "solver/sqp/sqp_solver.h"
#include "solver/terms/crease_geometry.h"

namespace sdog {
namespace {

// The largest side of the bounding box of the rest state.
double sheet_size(const Dofs& rest) {
  const auto p = rest.reshaped(3, rest.size() / 3);
  return (p.rowwise().maxCoeff() - p.rowwise().minCoeff()).maxCoeff();
}

}  // namespace

struct StandardMode::StraightFold {
  std::unique_ptr<StandardMode> mode;
  Dofs x;
  int iterations = 0;
};

StandardMode::StandardMode(DogProblem& problem, const Scenario& scenario,
                           const StandardOptions& options, std::optional<Dofs> origin)
    : problem_(problem),
      scenario_(scenario),
      options_(options),
      constraints_(problem, options.stitching),
      ladder_(problem.weights.fold_bias, options.max_fold_bias,
              [this](double weight) {
                problem_.weights.fold_bias = weight;
                sqp_->set_weight(kFoldBias, weight);
              }),
      substeps_(options.substep_step_length),
      held_(options.sqp.converged_decrease),
      settling_(options.settle, std::move(origin)),
      steps_{options.max_target_step * sheet_size(problem.rest()),
             options.max_angle_step * M_PI / 180} {
  scenario_.install(problem_);
  if (!scenario.keeps_folds) options_.folding = false;
  if (!options_.folding) problem_.weights.fold_bias = 0;  // before the solver reads the weights
  sqp_ = std::make_unique<SqpSolver>(problem_.mesh().vertex_count(), problem_.objective_terms(),
                                     constraints_.term(), options_.sqp);
}

StandardMode::~StandardMode() = default;

void StandardMode::set_time(double t) {
  scenario_.apply(problem_, t);
}

StepReport StandardMode::iterate(const IterationContext& ctx, Dofs& x) {
  set_time(ctx.t);
  return step(x, ctx.last());
}

bool StandardMode::solve(Dofs& x, bool last, int max_steps, StepReport& report,
                         double& constraint_max) {
  const SqpReport r = max_steps > 0 ? sqp_->converge(x, max_steps) : sqp_->iterate(x, last);
  report.work += r.work;
  report.step_length = r.step_length;
  constraint_max = r.constraint_max;
  report.failed = r.failed;
  report.failure = r.failure;
  if (max_steps > 0) report.converged = r.converged;
  return !r.failed;
}

StepReport StandardMode::step(Dofs& x, bool last) {
  // Every iteration: a patch mode before may have lowered it.
  set_blas_threads(options_.blas_threads > 0 ? options_.blas_threads : default_blas_threads());
  if (restore_first_) {
    restore_first_ = false;
    const SqpReport restored = sqp_->restore_constraints(x);
    if (restored.failed) {
      StepReport report;
      report.work = restored.work;
      report.failed = true;
      report.failure = restored.failure;
      return report;
    }
    StepReport report = options_.converge ? converge(x, last) : attempt(x, last, 0);
    report.work += restored.work;
    return report;
  }
  return options_.converge ? converge(x, last) : attempt(x, last, 0);
}

bool StandardMode::folded(const Dofs& x) const {
  return !options_.folding || check_folded(problem_.mesh(), problem_.free_sites, x).folded;
}

StepReport StandardMode::attempt(Dofs& x, bool last, int max_steps) {
  StepReport report;
  double& constraint_max = constraint_max_;  // of the last attempt
  if (!options_.folding) {
    solve(x, last, max_steps, report, constraint_max);
    return report;
  }
  const Dofs x0 = x;
  const Eigen::VectorXd lambda0 = sqp_->multipliers();
  if (!solve(x, last, max_steps, report, constraint_max)) return report;
  const FoldCheck check = check_folded(problem_.mesh(), problem_.free_sites, x);
  report.folded = check.folded;
  if (report.folded) {
    ladder_.to_base();
    return report;
  }
  const bool converging = max_steps > 0;
  if (converging && !ladder_.may_climb()) return report;
  escalate_fold_bias(x, x0, lambda0, last, max_steps, check.violations, constraint_max, report);
  if (converging && !report.folded) ladder_.climb_failed();
  return report;
}

StepReport StandardMode::converge(Dofs& x, bool last) {
  const Targets goal = Targets::of(problem_);
  settling_.begin_iteration(x);
  if (!goal_ || !goal_->matches(goal) || goal_->distance(goal, steps_) > 0) {
    goal_ = goal;
    settling_.new_goal();
    straight_.reset();
  }
  if (!reached_ || !reached_->matches(goal)) {
    reached_ = Targets::met_by(problem_, x);
    converged_ = false;
  }
  const double distance = reached_->distance(goal, steps_);
  if (distance > 0) {
    converged_ = false;
    held_.reset();
  }
  StepReport report;
  if (converged_ && !last) {  // nothing left to do but settling: no factorisation of x
    report.converged = true;
    if (settling_.wanted()) settle(x, report);
    return report;
  }
  // The last iteration from a converged folded state: what it falls back on (finish_folded).
  std::optional<std::pair<Dofs, Eigen::VectorXd>> converged_folded;
  if (last && converged_ && options_.folding && folded(x))
    converged_folded.emplace(x, sqp_->multipliers());
  ladder_.new_iteration();
  if (distance > 0) {
    report = follow(x, goal, distance);
  } else {  // held targets: steps until converged
    report = attempt(x, false, options_.max_iteration_steps);
    converged_ = !report.failed && report.converged.value_or(false);
    report.converged = converged_;
    report.target_fraction = report.failed ? 0 : 1;
  }
  // A raised fold bias serves the iteration that raised it only.
  if (options_.folding) ladder_.to_base();
  if (distance == 0 && !report.failed && !converged_ && !held_.lowers(sqp_->objective(x)) &&
      sqp_->constraint_values(x).lpNorm<Eigen::Infinity>() <= options_.sqp.constraint_tolerance) {
    converged_ = true;
    report.converged = true;
  }
  if (converged_ && !last && settling_.wanted()) settle(x, report);
  if (last && !report.failed) finish(x, report);
  if (converged_folded && (report.failed || !report.folded))
    finish_folded(x, *converged_folded, report);
  return report;
}

void StandardMode::finish_folded(Dofs& x, const std::pair<Dofs, Eigen::VectorXd>& converged,
                                 StepReport& report) {
  // The held steps of a last iteration can move a converged folded sheet to where the projection
  // unfolds it; the converged state projected without them is kept when it stays folded.
  Dofs y = converged.first;
  const Eigen::VectorXd lambda = sqp_->multipliers();
  const double constraint_max = constraint_max_;
  sqp_->set_multipliers(converged.second);
  StepReport again;
  again.converged = true;
  finish(y, again);
  report.work += again.work;
  if (!again.folded) {
    sqp_->set_multipliers(lambda);
    constraint_max_ = constraint_max;
    return;
  }
  x = y;
  again.work = report.work;
  report = std::move(again);
}

void StandardMode::settle(Dofs& x, StepReport& report) {
  if (!straight_) {
    StandardOptions options = options_;
    options.settle = false;
    straight_ = std::make_unique<StraightFold>();
    straight_->mode =
        std::make_unique<StandardMode>(problem_, scenario_, options);  // installs the scenario
    straight_->x = settling_.origin();
  }
  goal_->install(problem_);
  const StepReport r = straight_->mode->step(straight_->x, false);
  goal_->install(problem_);  // the straight fold may have stopped short of them
  report.work += r.work;
  ++straight_->iterations;
  const bool done = r.failed || (r.converged.value_or(false) && r.target_fraction >= 1);
  if (!done && straight_->iterations < SettlingPlan::kMaxIterations) {
    report.converged = false;
    report.stage = settling_stage::kRunning;
    return;
  }
  report.stage = settling_stage::kKept;
  if (done && !r.failed) {
    // Both compared as a run's last iteration leaves them, at the final constraint tolerance: the
    // projection there raises the objective by up to several percent, differently for each state.
    finish(x, report);
    StepReport straight;
    straight_->mode->finish(straight_->x, straight);
    report.work += straight.work;
    const double f = weighted_objective(problem_, x);
    const SettledFold run{report.folded, angle_agreement(problem_, x).all_against(), f};
    const SettledFold other{straight.folded, angle_agreement(problem_, straight_->x).all_against(),
                            weighted_objective(problem_, straight_->x)};
    if (straight_fold_wins(run, other,
                           options_.sqp.converged_decrease * std::max(std::abs(f), 1.0))) {
      x = straight_->x;
      sqp_->set_multipliers(straight_->mode->sqp().multipliers());
      report.stage = settling_stage::kReplaced;
      report.folded = true;
    }
  }
  straight_.reset();
  settling_.done();
  report.converged = true;
}

StepReport StandardMode::follow(Dofs& x, const Targets& goal, double distance) {
  // Distances count sub-steps of the largest size (steps_).
  if (SubstepSchedule::short_move(
          distance)) {  // targets that move little, as in the thesis protocol
    goal.install(problem_);
    StepReport report = attempt(x, false, 0);
    if (!report.failed) reached_ = goal;
    report.target_fraction = report.failed ? 0 : 1;
    report.converged = false;
    return report;
  }
  StepReport report;
  report.converged = false;
  std::optional<StepReport> rejected;  // the last sub-step not kept, when no later one was
  // Between sub-steps the constraints need only stay near: the state the iteration ends with is
  // restored to the constraint tolerance below, once.
  sqp_->set_restoration_tolerance(options_.substep_constraint_tolerance);
  for (int attempts = 0; attempts < options_.max_iteration_steps; ++attempts) {
    const double remaining = reached_->distance(goal, steps_);
    if (remaining == 0) break;
    const double s = substeps_.next(remaining);
    const Targets at = reached_->towards(goal, s);
    at.install(problem_);
    const Dofs x0 = x;
    const Eigen::VectorXd lambda0 = sqp_->multipliers();
    StepReport r = attempt(x, false, 1);
    report.work += r.work;
    if (substeps_.keeps(s, remaining, r.failed, r.step_length)) {
      reached_ = at;
      substeps_.kept();
      report.step_length = r.step_length;
      rejected.reset();
      continue;
    }
    x = x0;
    sqp_->set_multipliers(lambda0);
    rejected = std::move(r);
    if (SubstepSchedule::smallest(s)) break;  // x stays where it was, at the targets it met
    substeps_.rejected(s);
  }
  sqp_->set_restoration_tolerance(0);
  reached_->install(problem_);
  if (sqp_->constraint_values(x).lpNorm<Eigen::Infinity>() > options_.sqp.constraint_tolerance) {
    const SqpReport restored = sqp_->restore_constraints(x);
    report.work += restored.work;
    if (restored.failed) {
      report.failed = true;
      report.failure = restored.failure;
      return report;
    }
  }
  report.target_fraction = 1 - reached_->distance(goal, steps_) / distance;
  if (report.target_fraction == 0 && rejected &&
      rejected->failed) {  // not even the smallest sub-step
    report.failed = true;
    report.failure = rejected->failure;
  }
  report.folded = folded(x);
  return report;
}

void StandardMode::finish(Dofs& x, StepReport& report) {
  const double tolerance = options_.sqp.final_constraint_tolerance;
  constraints_.use_final_scale(true);
  constraint_max_ =
      sqp_->constraint_values(x).lpNorm<Eigen::Infinity>();  // x may be an earlier attempt's
  if (constraint_max_ > tolerance) {
    const Dofs x0 = x;
    const double constraint_max0 = constraint_max_;
    const double residual0 = iteration_residual(x);
    project(x, report);
    // The projection has a budget (polish_factorizations) and ends at its best state; one that
    // ends with larger residuals than it started (as the iterations measure them: its own scale
    // trades DOG rows for stitching gaps), or not finite, is dropped.
    if (!x.allFinite() || !(iteration_residual(x) <= residual0)) {
      x = x0;
      constraint_max_ = constraint_max0;
      constraints_.use_final_scale(false);
      report.folded = folded(x);
      return;
    }
    // The projection moves x least in the metric of the objective's Hessian, which may carry a fold
    // site across flat; a raised fold bias stiffens the metric there. A projection with it is kept
    // only when it folds the sheet without ending above the residuals it started from.
    if (!folded(x)) {
      const Dofs first = x;
      const double first_constraint_max = constraint_max_;
      double weight = ladder_.base();
      while (!folded(x) && raise_fold_bias(weight, report)) {
        x = x0;
        project(x, report);
      }
      ladder_.to_base();
      if (!folded(x) || !x.allFinite() || !(iteration_residual(x) <= residual0)) {
        x = first;
        constraint_max_ = first_constraint_max;
      }
    }
  }
  constraints_.use_final_scale(false);
  report.folded = folded(x);
}

double StandardMode::iteration_residual(const Dofs& x) {
  constraints_.use_final_scale(false);
  const double r = sqp_->constraint_values(x).lpNorm<Eigen::Infinity>();
  constraints_.use_final_scale(true);
  return r;
}

void StandardMode::project(Dofs& x, StepReport& report) {
  // The projection moves x least; where it stalls, the polish (with the constraints' curvature)
  // gets there.
  SqpReport finished = sqp_->project(x);
  if (finished.failed) finished.constraint_max = constraint_max_;
  if (finished.constraint_max > options_.sqp.final_constraint_tolerance) sqp_->polish(x, finished);
  report.work += finished.work;
  constraint_max_ = finished.constraint_max;
}

void StandardMode::escalate_fold_bias(Dofs& x, const Dofs& x0, const Eigen::VectorXd& lambda0,
                                      bool last, int max_steps, int violations,
                                      double constraint_max, StepReport& report) {
  // The attempt with the fewest unfolded sites so far (the lowest weight among equals) whose
  // constraints are as well met as the first attempt's (or to the solver's tolerance): what the
  // iteration keeps when no escalation folds the sheet.
  const double feasible = std::max(constraint_max, options_.sqp.constraint_tolerance);
  struct Attempt {
    Dofs x;
    Eigen::VectorXd lambda;
    int violations;
    double step_length;
    std::optional<bool> converged;
  } best{x, sqp_->multipliers(), violations, report.step_length, report.converged};
  // As in the reference: an escalated bias stays for the next iteration and returns to its base
  // value once an iteration ends folded.
  double weight = problem_.weights.fold_bias;
  while (!report.folded && raise_fold_bias(weight, report)) {
    x = x0;
    sqp_->set_multipliers(lambda0);
    if (!solve(x, last, max_steps, report,
               constraint_max)) {  // a retry the solver cannot take ends the escalation
      report.failed = false;
      report.failure.clear();
      break;
    }
    const FoldCheck check = check_folded(problem_.mesh(), problem_.free_sites, x);
    report.folded = check.folded;
    if (check.violations < best.violations && constraint_max <= feasible)
      best = {x, sqp_->multipliers(), check.violations, report.step_length, report.converged};
  }
  if (!report.folded && report.work.fold_retries > 0) {
    // Unlike the reference, which keeps the last attempt and the capped weight: past a point the
    // bias only wrecks the DOG constraints without folding (docs/design/rejected.md).
    x = best.x;
    sqp_->set_multipliers(best.lambda);
    report.step_length = best.step_length;
    report.converged = best.converged;
    ladder_.to_base();
  }
}

void StandardMode::start_from(const Dofs&) {
  sqp_->set_multipliers(Eigen::VectorXd::Zero(sqp_->multipliers().size()));
  settling_.restart();
  goal_.reset();
  straight_.reset();
  restore_first_ = options_.stitching == Stitching::kExact;
  reached_.reset();
  held_.reset();
  substeps_.reset();
  converged_ = false;
  if (options_.folding) ladder_.to_base();
}

void StandardMode::set_folding(bool on) {
  options_.folding = on;
  if (on)
    ladder_.to_base();
  else
    ladder_.off();
}

bool StandardMode::raise_fold_bias(double& weight, StepReport& report) {
  if (!ladder_.raise(weight)) return false;
  ++report.work.fold_retries;
  return true;
}

}  // namespace sdog
