#pragma once
// Solver modes by name (`sdog run --mode`, `sdog bench --modes`).
#include <memory>
#include <string>
#include <vector>

#include "geometry/dog_model.h"
#include "solver/modes/mode.h"
#include "solver/run/run.h"
#include "solver/run/run_config.h"

namespace sdog {

/// The names `make_mode` accepts, in the order of the documentation.
std::vector<std::string> mode_names();
/// The names, comma separated (for help texts and messages).
std::string known_modes();
/// Throws UsageError "`what`unknown mode 'name' (known: ...)" unless `name` is a mode.
void check_mode_name(const std::string& name, const std::string& what = "");
/// True when the mode needs the coarse mesh and the fine-coarse map.
bool mode_needs_coarse(const std::string& name);

/// Throws UsageError when mode `name` cannot run on the model (unknown name, no coarse mesh for a
/// coarse mode): the check a run makes before the work for every mode it will use.
void check_mode_usable(const std::string& name, const DogModel& model);

/// The mode `name` on the problem (which must outlive it) with the config's solver options.
/// Throws UsageError for unknown names.
/// `model` (needed by the coarse modes, mode_needs_coarse) must outlive the mode.
std::unique_ptr<Mode> make_mode(const std::string& name, DogProblem& problem, const Scenario& scenario,
                                const RunConfig& config, const DogModel* model = nullptr);

/// A mode taking over a run at state x (`sdog run --switch`, the studio's mode menu): the problem's
/// weights return to the configuration's (the standard mode raises the fold bias while folding),
/// the mode is made as by make_mode and derives its own state from x (Mode::start_from). The mode
/// that ran before must not iterate again: the new one owns the problem's blocks.
std::unique_ptr<Mode> switch_mode(const std::string& name, DogProblem& problem, const Scenario& scenario,
                                  const RunConfig& config, const DogModel& model, const Dofs& x);

/// The schedule of config.switches for run_scenario: at each switch's iteration the mode in
/// `current` is replaced by switch_mode's (so `current` always owns the running mode). Every
/// argument must outlive the run.
ModeSchedule switch_schedule(DogProblem& problem, const Scenario& scenario, const RunConfig& config,
                             const DogModel& model, std::unique_ptr<Mode>& current);

}  // namespace sdog
