#pragma once
// A whole run of a mode in a test: the summary, every iteration's report and the final state.
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

/// Runs `mode` with the configuration's scenario on the model's fine mesh.
inline RunResult run_mode(const std::string& mode_name, const DogModel& model, const RunConfig& config) {
  DogProblem problem(model.fine, model.fine_topology, config.weights);
  const Scenario scenario = make_scenario(config, model.fine);
  auto mode = make_mode(mode_name, problem, scenario, config, &model);
  RunResult r;
  r.x = scenario.start(model.fine);
  Recorder recorder;
  r.summary = run_scenario(*mode, problem, scenario, r.x, {&recorder});
  r.reports = recorder.reports;
  return r;
}

}  // namespace sdog::test
