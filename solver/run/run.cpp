#include "solver/run/run.h"

#include <cmath>

#include "base/stopwatch.h"
#include "base/text_format.h"
#include "solver/problem/targets.h"

namespace sdog {

bool within_final_tolerance(const Diagnostics& d, double final_constraint_tolerance) {
  return d.dog_max <= 2 * final_constraint_tolerance &&
         d.stitch_gap_max <= 2 * final_constraint_tolerance;
}

IterationReport run_iteration(Mode& mode, DogProblem& problem, const Scenario& scenario, Dofs& x,
                              int iteration, int iterations_left) {
  IterationReport report;
  report.iteration = iteration;
  report.mode = mode.name();
  report.t = scenario.time_of(iteration);
  IterationContext ctx;
  ctx.t = report.t;
  if (iterations_left != 0) ctx.next_t = scenario.time_of(iteration + 1);
  ctx.iterations_left = iterations_left;
  const Dofs x_before = x;
  const auto t0 = Clock::now();
  report.step = mode.iterate(ctx, x);
  report.iteration_ms = ms_since(t0);
  report.diagnostics = diagnose(problem, x);
  const Diagnostics& d = report.diagnostics;
  if (!report.step.failed &&
      (!std::isfinite(d.objective) || !(d.dog_max <= kDivergedDogResidual))) {
    report.step.failed = true;
    report.step.failure = "the state diverged (DOG residual " + format_number(d.dog_max) +
                          ", objective " + format_number(d.objective) + ")";
  }
  if (report.step.failed) {
    x = x_before;
    return report;
  }
  if (report.t < 1 || report.step.target_fraction < 1) {
    const Targets reported = Targets::of(problem);  // those the mode reports x for
    scenario.apply(problem, 1.0);
    report.objective_final_targets = weighted_objective(problem, x);
    reported.install(problem);
  } else {
    report.objective_final_targets = report.diagnostics.objective;
  }
  return report;
}

RunSummary run_scenario(Mode& mode, DogProblem& problem, const Scenario& scenario, Dofs& x,
                        const std::vector<RunObserver*>& observers, const std::atomic<bool>* cancel,
                        const ModeSchedule& schedule) {
  Mode* current = &mode;
  const auto start = Clock::now();
  RunSummary summary;
  const int total = scenario.iterations + scenario.hold;
  for (int k = 1; k <= total; ++k) {
    if (cancel && cancel->load()) {
      summary.termination = Termination::kCancelled;
      break;
    }
    if (schedule)
      if (Mode* next = schedule(k, x)) current = next;
    IterationReport report = run_iteration(*current, problem, scenario, x, k, total - k);
    report.elapsed_ms = ms_since(start);
    for (RunObserver* o : observers) o->on_iteration(report, x);
    summary.last = report;
    if (report.step.failed) {
      summary.termination = Termination::kFailed;
      summary.failure = "iteration " + std::to_string(k) + ": " + report.step.failure;
      break;
    }
    summary.iterations = k;
  }
  summary.seconds = ms_since(start) / 1000;
  return summary;
}

}  // namespace sdog
