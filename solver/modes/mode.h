#pragma once
// A solver mode: how one iteration of a deformation run is computed. Modes share the iteration
// context, the step report, the scenario and the diagnostics; the run driver (run/run.h) is mode
// independent.
#include <optional>
#include <string>
#include <vector>

#include "solver/modes/mode_kind.h"
#include "solver/patches/patch_report.h"
#include "solver/problem/scenario.h"
#include "solver/sqp/work.h"
#include "solver/terms/term.h"

namespace sdog {

/// What a mode is told about the iteration it computes.
struct IterationContext {
  static constexpr int kOpenEnded = -1;
  double t = 0;                  ///< scenario time of the targets
  std::optional<double> next_t;  ///< of the next iteration; none in a run's last one
  /// Iterations of the run after this one (0 in its last), or kOpenEnded when the run has no set
  /// end (the studio).
  int iterations_left = kOpenEnded;
  /// The run's last iteration, which ends with the constraints at the final tolerance.
  bool last() const { return iterations_left == 0; }
};

/// Solver-side facts of one iteration (the run driver adds the diagnostics).
struct StepReport {
  Work work;
  double step_length = 0;
  bool folded = true;
  /// The state meets the KKT tolerance for the targets it reports (standard iterations that
  /// converge; unknown for the others).
  std::optional<bool> converged;
  /// How far along this iteration's requested target motion the reported targets are (1: all
  /// the way; less when a converging iteration approached far targets in sub-steps).
  double target_fraction = 1;
  /// What a mode's own policy did in the iteration besides its steps, as the run log's `settling`
  /// column shows it (the standard mode's settling, settling_plan.h); empty: nothing.
  std::string stage;
  bool failed = false;
  std::string failure;               ///< why; the mode rolled x back
  std::vector<PatchReport> patches;  ///< per-patch solves of the multi-patch modes, in patch order
};

class Mode {
 public:
  virtual ~Mode() = default;
  virtual ModeKind kind() const = 0;
  const char* name() const { return enum_name(kind()); }
  /// One iteration on the fine positions x with the targets of ctx.t (rolled back on failure).
  virtual StepReport iterate(const IterationContext& ctx, Dofs& x) = 0;
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
