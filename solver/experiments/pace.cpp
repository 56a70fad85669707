#include "solver/experiments/pace.h"

#include <algorithm>
#include <limits>

#include "base/stopwatch.h"
#include "solver/run/run.h"
#include "solver/run/run_setup.h"

namespace sdog {
namespace {

double handle_distance(const DogProblem& problem, const Dofs& x) {
  double d = 0;
  Eigen::Vector3d p[LinearPointTerm::kMaxVertices];
  for (int b = 0; b < problem.positions.block_count(); ++b) {
    gather_block(problem.positions, b, x, p);
    Eigen::Vector3d r;
    problem.positions.evaluate(b, p, r.data(), nullptr);
    d = std::max(d, r.norm());
  }
  return d;
}

// The configuration's scenario over k iterations, then held (run_pace).
PaceResult run_paced(const DogModel& model, RunConfig config, int k, int max_hold);

}  // namespace

PaceResult run_pace(const DogModel& model, RunConfig config, int k, int max_hold) {
  config.scenario = ScenarioKind::kCorners;
  return run_paced(model, config, k, max_hold);
}

PaceResult run_fold_pace(const DogModel& model, RunConfig config, int k, int max_hold) {
  config.scenario = ScenarioKind::kFold;
  return run_paced(model, config, k, max_hold);
}

namespace {

PaceResult run_paced(const DogModel& model, RunConfig config, int k, int max_hold) {
  config.iterations = k;
  config.hold = max_hold;
  config.switches.clear();
  RunSetup setup(model, ModeKind::kStandard, config);
  PaceResult result;
  result.k = k;
  const int total = setup.total_iterations();
  const auto start = Clock::now();
  bool finishing = false;
  for (int i = 1; i <= total; ++i) {
    const int left = finishing ? 0 : total - i;
    const IterationReport r =
        run_iteration(setup.mode(), setup.problem(), setup.scenario(), setup.positions(), i, left);
    result.iterations = i;
    result.factorizations += r.step.work.factorizations;
    if (r.step.failed) {
      result.failure = "iteration " + std::to_string(i) + ": " + r.step.failure;
      break;
    }
    result.objective = r.diagnostics.objective;
    result.dog_max = r.diagnostics.dog_max;
    result.stitch_gap_max = r.diagnostics.stitch_gap_max;
    result.sheet_strain_max = r.diagnostics.sheet_strain_max;
    result.folded = r.step.folded;
    result.positions = r.diagnostics.terms[kPositions];
    result.angles = r.diagnostics.angles_met;
    const bool converged =
        i >= k && r.t >= 1 && r.step.target_fraction >= 1 && r.step.converged.value_or(false);
    // The last iteration ends on the final tolerance: it counts as converged only if it meets it.
    result.converged =
        finishing
            ? within_final_tolerance(r.diagnostics, config.standard.sqp.final_constraint_tolerance)
            : converged;
    if (left == 0) break;
    if (converged && !result.time_to_shape_s) {
      result.time_to_shape_s = ms_since(start) / 1000;
      finishing = true;  // the next iteration is the last
    }
  }
  result.total_s = ms_since(start) / 1000;
  result.handle_distance = handle_distance(setup.problem(), setup.positions());
  return result;
}

}  // namespace

std::vector<double> objective_ratios(const std::vector<PaceResult>& results) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& r : results)
    if (r.failure.empty()) best = std::min(best, r.objective);
  std::vector<double> ratios;
  for (const auto& r : results) ratios.push_back(r.objective / best);
  return ratios;
}

}  // namespace sdog
