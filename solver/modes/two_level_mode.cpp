#include "solver/modes/two_level_mode.h"

#include <cmath>

#include "solver/modes/final_projection.h"
#include "solver/sqp/sqp_solver.h"

namespace sdog {
namespace {

SubsolverOptions with_fold_sharpness(SubsolverOptions o, double k) {
  o.fold_sharpness = k;
  return o;
}

}  // namespace

TwoLevelMode::TwoLevelMode(DogProblem& fine, const DogModel& model, const Scenario& scenario,
                           const TwoLevelOptions& options, const StandardOptions& standard,
                           const SubsolverOptions& subsolvers)
    : problem_(fine),
      scenario_(scenario),
      standard_(standard),
      options_(options),
      coarse_(fine, model, scenario, options.link_weight, standard, ModeKind::kTwoLevel,
              options.fold_sharpness),
      fine_(fine, scenario, with_fold_sharpness(subsolvers, options.fold_sharpness), standard.sqp) {
}

StepReport TwoLevelMode::iterate(const IterationContext& ctx, Dofs& x) {
  begin_finish_if_due(ctx.iterations_left);
  if (finish_) {
    finish_->set_time(ctx.t);
    return finish_iteration(x, ctx.last());
  }
  coarse_.set_time(ctx.t);
  fine_.set_time(ctx.t);
  return two_level_iteration(ctx, x);
}

void TwoLevelMode::start_from(const Dofs& x) {
  coarse_.start_from(x);
  shares_left_ = 0;  // a coarse step first, from the new coarse state
}

void TwoLevelMode::begin_finish_if_due(int left) {
  if (finish_ || left == IterationContext::kOpenEnded || left >= options_.standard_finish) return;
  // As a switch to the standard mode (mode_factory.h): it installs the scenario's blocks in the
  // fine problem, whose weights the two-level mode left as configured. Fold retries only up to the
  // cap: from sites the two-level iterations left across their crease, the escalation to the
  // standard's 1e14 wrecks the sheet, while one step of x10 refolds the sites that are close
  // (docs/design/rejected.md).
  StandardOptions options = standard_;
  options.max_fold_bias = problem_.weights.fold_bias * options_.finish_fold_bias_cap;
  options.converge = false;  // the finish's steps per iteration are the thesis's
  finish_ = std::make_unique<StandardMode>(problem_, scenario_, options);
}

StepReport TwoLevelMode::finish_iteration(Dofs& x, bool last) {
  // The last one is an ordinary standard iteration and the projection onto the constraints, not
  // the standard's polish: its exact-Hessian steps rely on multipliers settled over a whole run,
  // and after a few standard iterations they move the sheet far (docs/design/rejected.md).
  const Dofs x0 = last ? x : Dofs();
  StepReport report = finish_->step(x, false);
  if (last && !report.failed && !add_projection(finish_->sqp().project(x), report))
    x = x0;  // rolled back
  return report;
}

StepReport TwoLevelMode::two_level_iteration(const IterationContext& ctx, Dofs& x) {
  const bool last = ctx.last();
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
  const bool next_is_two_level = ctx.iterations_left == IterationContext::kOpenEnded ||
                                 ctx.iterations_left - 1 >= options_.standard_finish;
  StepReport report;
  coarse_.run_beside([&] { report = fine_.round(x, last); },
                     options_.concurrent_coarse && !last && next_is_two_level && shares_left_ == 0
                         ? ctx.next_t
                         : std::nullopt);
  if (report.failed) {
    x = x0;
    coarse_.set_state(c0);
    shares_left_ = shares0;  // the share changed only if a coarse step is due again
    report.failure = "fine step: " + report.failure;
    return report;
  }
  report.work += coarse.work;
  return report;
}

}  // namespace sdog
