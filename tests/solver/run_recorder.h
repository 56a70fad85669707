#pragma once
// A whole run of a mode in a test: the summary, every iteration's report and the final state.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "solver/modes/mode_factory.h"
#include "solver/problem/diagnostics.h"
#include "solver/run/run.h"
#include "solver/run/run_config.h"
#include "solver/run/run_setup.h"

namespace sdog::test {

/// Collects the report of every iteration.
struct Recorder : RunObserver {
  std::vector<IterationReport> reports;
  void on_iteration(const IterationReport& r, const Dofs&) override { reports.push_back(r); }
};

struct RunResult {
  RunSummary summary;
  std::vector<IterationReport> reports;
  Dofs x;
};

inline RunResult run_setup(RunSetup& setup) {
  RunResult r;
  Recorder recorder;
  r.summary = setup.run({&recorder});
  r.reports = recorder.reports;
  r.x = setup.positions();
  return r;
}

/// Runs `mode` with `scenario` (made from the configuration) on the model's fine mesh.
inline RunResult run_mode(const std::string& mode_name, const DogModel& model,
                          const RunConfig& config, const Scenario& scenario) {
  RunSetup setup(model, parse_enum<ModeKind>(mode_name), config, scenario);
  return run_setup(setup);
}

/// Runs `mode` with the configuration's scenario on the model's fine mesh.
inline RunResult run_mode(const std::string& mode_name, const DogModel& model,
                          const RunConfig& config) {
  RunSetup setup(model, parse_enum<ModeKind>(mode_name), config);
  return run_setup(setup);
}

/// The configuration of the thesis preset (soft stitching): for tests of the thesis's solver and of
/// the patch modes measured against it.
inline RunConfig thesis_config() {
  RunConfig config;
  config.preset = Preset::kThesis;
  apply_preset(config.preset, config);
  return config;
}

/// The thesis preset with the given iteration counts.
inline RunConfig thesis_run(int iterations, int hold) {
  RunConfig config = thesis_config();
  config.iterations = iterations;
  config.hold = hold;
  return config;
}

/// The default configuration with the given iteration counts.
inline RunConfig short_run(int iterations, int hold) {
  RunConfig config;
  config.iterations = iterations;
  config.hold = hold;
  return config;
}

/// Every iteration of a multi-patch mode: DOG residual below 1e-4 and one converged report with a
/// time per patch.
inline void expect_dog_and_patch_reports(const RunResult& r, int patch_count) {
  for (const auto& rep : r.reports) {
    EXPECT_LT(rep.diagnostics.dog_max, 1e-4) << "iteration " << rep.iteration;
    ASSERT_EQ(static_cast<int>(rep.step.patches.size()), patch_count);
    for (const auto& p : rep.step.patches) {
      EXPECT_TRUE(p.converged) << "iteration " << rep.iteration << " patch " << p.patch;
      EXPECT_GT(p.ms, 0);
    }
  }
}

/// A patch mode follows dihedral angle constraints across patches (their blocks are kept with the
/// other patch frozen): on the fold scenario the angle residual ends far below that of the same run
/// with the angle weight 0, and the DOG constraints hold every iteration.
inline void expect_follows_angles(const std::string& mode_name, const DogModel& model) {
  RunConfig config = short_run(20, 10);
  config.scenario = ScenarioKind::kFold;
  config.fold_angle = 60;
  const RunResult with = run_mode(mode_name, model, config);
  ASSERT_FALSE(with.summary.failed()) << mode_name << ": " << with.summary.failure;
  for (const auto& rep : with.reports)
    EXPECT_LT(rep.diagnostics.dog_max, 1e-4) << mode_name << " " << rep.iteration;
  config.weights.angles = 0;
  const RunResult without = run_mode(mode_name, model, config);
  ASSERT_FALSE(without.summary.failed()) << mode_name << ": " << without.summary.failure;
  const double a = with.reports.back().diagnostics.terms[kAngles];
  EXPECT_LT(a, 0.1 * without.reports.back().diagnostics.terms[kAngles]) << mode_name;
}

/// A fixed point of a patch mode is a stationary point of the whole objective: started from the
/// standard solver's end state with the final targets held, `iterations` iterations of the mode
/// stay within 1% of its objective and its stitching gap. (Both with the thesis's soft stitching:
/// the patch modes stitch softly.)
inline void expect_standard_end_is_a_fixed_point(const std::string& mode_name,
                                                 const DogModel& model, int iterations) {
  const RunConfig config = thesis_run(60, 40);
  const Scenario scenario = make_scenario(config, model.fine);
  const RunResult standard = run_mode("standard", model, config, scenario);
  ASSERT_FALSE(standard.summary.failed()) << standard.summary.failure;
  DogProblem problem(model.fine, model.fine_topology, config.weights);
  auto mode = make_mode(parse_enum<ModeKind>(mode_name), problem, scenario, config, &model);
  Dofs x = standard.x;
  scenario.apply(problem, 1.0);  // the final targets, held
  const Diagnostics start = diagnose(problem, x);
  for (int k = 0; k < iterations; ++k) {
    IterationContext held;
    held.t = 1;
    held.iterations_left = iterations - 1 - k;
    const StepReport r = mode->iterate(held, x);
    ASSERT_FALSE(r.failed) << mode_name << " " << k << ": " << r.failure;
  }
  const Diagnostics end = diagnose(problem, x);
  EXPECT_NEAR(end.objective, start.objective, 0.01 * start.objective) << mode_name;
  EXPECT_NEAR(end.stitch_gap_max, start.stitch_gap_max, 0.01 * start.stitch_gap_max + 1e-4)
      << mode_name;
  EXPECT_LT(end.dog_max, 1e-5) << mode_name;
}

}  // namespace sdog::test
