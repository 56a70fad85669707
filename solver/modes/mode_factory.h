#pragma once
// Solver modes made by kind (mode_kind.h) with their options (mode_options.h).
#include <memory>

#include "geometry/mesh/dog_model.h"
#include "solver/modes/mode.h"
#include "solver/modes/mode_options.h"
#include "solver/problem/dog_problem.h"

namespace sdog {

/// Throws UsageError when `mode` cannot run on the model (a coarse mode without the coarse mesh, a
/// mode other than standard on a pattern with slits):
/// the check a run makes before the work for every mode it will use.
void check_mode_usable(ModeKind mode, const DogModel& model);

/// The mode on the problem (which must outlive it) with its options. `model` (needed by the coarse
/// modes, mode_needs_coarse) must outlive the mode. `origin`: the state the run started from when
/// the mode's first iteration does not start there (the studio makes a new mode after every edit);
/// the standard mode settles from it (settling_plan.h), the others do not use it.
std::unique_ptr<Mode> make_mode(ModeKind mode, DogProblem& problem, const Scenario& scenario,
                                const ModeOptions& options, const DogModel* model = nullptr,
                                const Dofs* origin = nullptr);

/// A mode taking over a run at state x (`sdog run --switch`, the studio's mode menu): the problem's
/// weights return to `weights` (the standard mode raises the fold bias while folding), the mode is
/// made as by make_mode (with `origin`) and derives its own state from x (Mode::start_from). The
/// mode that ran before must not iterate again: the new one owns the problem's blocks.
std::unique_ptr<Mode> switch_mode(ModeKind mode, DogProblem& problem, const Scenario& scenario,
                                  const ModeOptions& options, const Weights& weights,
                                  const DogModel& model, const Dofs& x,
                                  const Dofs* origin = nullptr);

}  // namespace sdog
