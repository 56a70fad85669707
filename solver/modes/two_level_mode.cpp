#include "solver/modes/two_level_mode.h"

#include <cmath>

#include "solver/modes/final_projection.h"

namespace sdog {
namespace {

SubsolverOptions with_fold_sharpness(SubsolverOptions o, double k) {
  o.fold_sharpness = k;
  return o;
}

void add_coarse(const StepReport& coarse, StepReport& report) {
  report.sqp_steps += coarse.sqp_steps;
  report.factorizations += coarse.factorizations;
  report.restoration_steps += coarse.restoration_steps;
  report.fold_retries += coarse.fold_retries;
  report.factor_ms += coarse.factor_ms;
}

}  // namespace

std::string TwoLevelOptions::validate() const {
  if (!(link_weight >= 0)) return "link_weight must be >= 0";
  if (!(fold_sharpness > 0) || !std::isfinite(fold_sharpness)) return "fold_sharpness must be a finite number > 0";
  if (standard_finish < 0) return "standard_finish must be >= 0";
  if (!(finish_fold_bias_cap >= 1) || !std::isfinite(finish_fold_bias_cap))
    return "finish_fold_bias_cap must be a finite number >= 1";
  if (coarse_every < 1) return "coarse_every must be >= 1";
  return "";
}

TwoLevelMode::TwoLevelMode(DogProblem& fine, const DogModel& model, const Scenario& scenario,
                           const TwoLevelOptions& options, const StandardOptions& standard,
                           const SubsolverOptions& subsolvers)
    : problem_(fine),
      scenario_(scenario),
      standard_(standard),
      options_(options),
      coarse_(fine, model, scenario, options.link_weight, standard, "twolevel",
              options.fold_sharpness),
      fine_(fine, scenario, with_fold_sharpness(subsolvers, options.fold_sharpness), standard.sqp) {}

void TwoLevelMode::set_time(double t) {
  if (finish_) return finish_->set_time(t);
  coarse_.set_time(t);
  fine_.set_time(t);
}

void TwoLevelMode::start_from(const Dofs& x) {
  coarse_.start_from(x);
  shares_left_ = 0;  // a coarse step first, from the new coarse state
}

void TwoLevelMode::set_iterations_left(int left) {
  iterations_left_ = left;
  if (finish_ || left == kOpenEnded || left >= options_.standard_finish) return;
  // As a switch to the standard mode (mode_factory.h): it installs the scenario's blocks in the
  // fine problem, whose weights the two-level mode left as configured. Fold retries only up to the
  // cap: from the sites the two-level iterations left across their crease the escalation to 1e14
  // wrecked the sheet (valley 61x61: objective 6.4e9 in the first finishing iteration, 30.6 at the
  // end, against 1.59 without retries), while one step of x10 refolds sites that are close (30
  // iterations: parallel_curves_4 27x45 folded at 3.14 instead of unfolded at 3.15, valley 41x41
  // folded at 2.64 instead of unfolded at 6.76; docs/solver-modes.md, "The two-level mode's
  // standard finish").
  StandardOptions options = standard_;
  options.max_fold_bias = problem_.weights.fold_bias * options_.finish_fold_bias_cap;
  finish_ = std::make_unique<StandardMode>(problem_, scenario_, options);
}

StepReport TwoLevelMode::finish_iteration(Dofs& x, bool last) {
  // The last one is an ordinary standard iteration and the projection onto the constraints, not
  // the standard's polish: its exact-Hessian steps rely on multipliers settled over a whole run,
  // and after a few standard iterations they moved the sheet far (4_corners 81x81, 10 finishing
  // iterations: objective 2.33 at iteration 299, 6.67 after the polish).
  const Dofs x0 = last ? x : Dofs();
  StepReport report = finish_->iterate(x, false);
  if (last && !report.failed && !add_projection(finish_->sqp().project(x), report)) x = x0;  // rolled back
  return report;
}

StepReport TwoLevelMode::iterate(Dofs& x, bool last) {
  if (finish_) return finish_iteration(x, last);
  const Dofs x0 = x, c0 = coarse_.state();
  const int shares0 = shares_left_;
  StepReport coarse;
  if (shares_left_ == 0) {
    coarse = coarse_.step(x);
    if (coarse.failed) {
      coarse.failure = "coarse step: " + coarse.failure;
      return coarse;
    }
    const Prolongation& P = coarse_.prolongation();
    correction_share_ = (P.apply(coarse_.state()) - P.apply(c0)) / options_.coarse_every;
    shares_left_ = options_.coarse_every;
  }
  x += correction_share_;
  --shares_left_;
  // The next iteration's coarse step beside the round, unless there is none: the run's last
  // iteration, the next one belongs to the standard finish or takes no coarse step.
  const bool next_is_two_level = iterations_left_ == kOpenEnded || iterations_left_ - 1 >= options_.standard_finish;
  StepReport report;
  coarse_.run_beside([&] { report = fine_.iterate(x, last); },
                     options_.concurrent_coarse && !last && next_is_two_level && shares_left_ == 0 ? next_time_
                                                                                                   : std::nullopt);
  if (report.failed) {
    x = x0;
    coarse_.set_state(c0);
    shares_left_ = shares0;  // the share changed only if a coarse step is due again
    report.failure = "fine step: " + report.failure;
    return report;
  }
  add_coarse(coarse, report);
  return report;
}

}  // namespace sdog
