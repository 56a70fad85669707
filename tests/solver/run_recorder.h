#pragma once
// A whole run of a mode in a test: the summary, every iteration's report and the final state.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geometry/dog_model.h"
#include "solver/mode_factory.h"
#include "solver/run.h"
#include "solver/run_config.h"

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

/// Runs `mode` with `scenario` on the model's fine mesh.
inline RunResult run_mode(const std::string& mode_name, const DogModel& model, const RunConfig& config,
                          const Scenario& scenario) {
  DogProblem problem(model.fine, model.fine_topology, config.weights);
  auto mode = make_mode(mode_name, problem, scenario, config, &model);
  RunResult r;
  r.x = scenario.start(model.fine);
  Recorder recorder;
  r.summary = run_scenario(*mode, problem, scenario, r.x, {&recorder});
  r.reports = recorder.reports;
  return r;
}

/// Runs `mode` with the configuration's scenario on the model's fine mesh.
inline RunResult run_mode(const std::string& mode_name, const DogModel& model, const RunConfig& config) {
  return run_mode(mode_name, model, config, make_scenario(config, model.fine));
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

}  // namespace sdog::test
