#pragma once
// The one way to set up a deformation run of a mode on a model from a run configuration: the
// command line, bench and compare, `sdog render`, the studio's session and the tests all go
// through make_scenario and RunSetup.
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "solver/modes/mode.h"
#include "solver/problem/dog_problem.h"
#include "solver/problem/scenario.h"
#include "solver/run/run.h"
#include "solver/run/run_config.h"

namespace sdog {

/// The configuration's scenario on the model's fine mesh: the named one (for flatten, its folded
/// start state is computed here by a short standard run) plus the listed constraints. Throws
/// InputError for vertex, crease-point or curve indices that do not exist (naming the JSON path),
/// UsageError and SolverError from the flatten scenario.
Scenario make_scenario(const RunConfig& config, const DogMesh& mesh);

/// Throws UsageError when the scenario has no targets (the fold scenario on a pattern without fold
/// sites at this resolution, `none` without constraints); `where` names the pattern and resolution.
void check_scenario_targets(const Scenario& scenario, const RunConfig& config,
                            const std::string& where);

/// A run of `mode` over the configuration's scenario on the model's fine mesh, from the
/// scenario's start state, with the configuration's mode switches.
class RunSetup {
 public:
  /// Builds and checks everything before any iteration: the scenario has targets and every mode
  /// of the run can run on the model (UsageError), constraint indices exist (InputError). The
  /// model must outlive the setup.
  RunSetup(const DogModel& model, ModeKind mode, const RunConfig& config);
  /// The same with the configuration's scenario made already (make_scenario), e.g. to reuse an
  /// expensive start state for several runs.
  RunSetup(const DogModel& model, ModeKind mode, const RunConfig& config, Scenario scenario);
  ~RunSetup();
  RunSetup(const RunSetup&) = delete;
  RunSetup& operator=(const RunSetup&) = delete;

  const DogModel& model() const { return model_; }
  const RunConfig& config() const { return config_; }
  DogProblem& problem() { return *problem_; }
  const Scenario& scenario() const { return scenario_; }
  /// The mode computing the run (the latest after a switch).
  Mode& mode() { return *mode_; }
  /// The fine positions: the start state, then the state after the last iteration run.
  Dofs& positions() { return x_; }
  int total_iterations() const { return scenario_.iterations + scenario_.hold; }
  /// "PATTERN at XxY" for messages.
  std::string where() const;

  /// Runs every iteration of the scenario (or until it fails or `cancel` is raised).
  RunSummary run(const std::vector<RunObserver*>& observers,
                 const std::atomic<bool>* cancel = nullptr);

 private:
  const DogModel& model_;
  RunConfig config_;
  std::unique_ptr<DogProblem> problem_;
  Scenario scenario_;
  std::unique_ptr<Mode> mode_;
  Dofs x_;
};

}  // namespace sdog
