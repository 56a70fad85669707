#pragma once
// A solver mode: how one iteration of a deformation run is computed. Modes share the iteration
// report, the scenario and the diagnostics; the run driver (run.h) is mode independent.
#include <optional>
#include <string>
#include <vector>

#include "solver/patches/patch_report.h"
#include "solver/problem/scenario.h"
#include "solver/terms/term.h"

namespace sdog {

/// Solver-side facts of one iteration (the run driver adds the diagnostics).
struct StepReport {
  int sqp_steps = 0;
  int factorizations = 0;
  int restoration_steps = 0;
  double step_length = 0;
  int fold_retries = 0;
  bool folded = true;
  double factor_ms = 0;  ///< numeric factorisation and triangular solves
  bool failed = false;
  std::string failure;  ///< why; the mode rolled x back
  std::vector<PatchReport> patches;  ///< per-patch solves of the multi-patch modes, in patch order
};

class Mode {
 public:
  virtual ~Mode() = default;
  virtual const char* name() const = 0;
  /// Sets every target the mode uses for scenario time t in [0, 1].
  virtual void set_time(double t) = 0;
  /// One iteration on the fine positions x (rolled back on failure). `last`: the run's last
  /// iteration, which ends with the constraints restored to the final tolerance.
  virtual StepReport iterate(Dofs& x, bool last) = 0;
  /// Called before every iteration (before set_time): how many iterations the run has after it (0
  /// in its last one), or kOpenEnded when the run has no set end (the studio). Only twolevel uses
  /// it, for its standard finish (two_level_mode.h).
  virtual void set_iterations_left(int /*left*/) {}
  static constexpr int kOpenEnded = -1;
  /// Called before every iteration (after set_time): the scenario time of the next iteration, or
  /// nothing in a run's last one. The two-resolution modes compute the next coarse step ahead,
  /// beside this iteration's fine round (coarse_level.h).
  virtual void set_next_time(std::optional<double> /*t*/) {}
  /// Takes x as the state the next iteration starts from although the mode did not compute it
  /// (another mode ran before it): a mode with state of its own besides x (the coarse positions of
  /// the two-resolution modes) derives that state from x. Fresh modes of the other kinds need
  /// nothing: their multipliers and targets start from x in their first iteration.
  virtual void start_from(const Dofs& /*x*/) {}
  /// The coarse DOG's current state for modes that step a coarse mesh (coarse, twolevel), else
  /// nullptr; pictures and the studio show it next to the fine mesh.
  virtual const Dofs* coarse_positions() const { return nullptr; }
};

}  // namespace sdog
