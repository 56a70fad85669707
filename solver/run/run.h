#pragma once
// A deformation run: the scenario's iterations (targets moving, then held), each computed by a
// mode and reported with the same diagnostics, to observers (run log, frames, progress, GUI).
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "base/enum_names.h"
#include "solver/modes/mode.h"
#include "solver/problem/diagnostics.h"

namespace sdog {

struct IterationReport {
  int iteration = 0;  ///< 1-based
  std::string mode;   ///< the mode that computed it
  double t = 0;       ///< scenario time of the targets
  Diagnostics diagnostics;
  double objective_final_targets = 0;  ///< weighted objective with the targets of t = 1
  StepReport step;
  double iteration_ms = 0;
  double elapsed_ms = 0;  ///< since the run started (set by run_scenario)
};

/// Receives every iteration (and the state after it).
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void on_iteration(const IterationReport& report, const Dofs& x) = 0;
};

/// Why a run ended.
enum class Termination {
  kCompleted,  ///< every iteration of the scenario
  kFailed,     ///< an iteration failed (rolled back: x is the last good state)
  kCancelled,  ///< the cancel flag was raised
};
template <>
struct EnumNames<Termination> {
  static constexpr const char* noun = "termination";
  static constexpr EnumName<Termination> rows[] = {
      {Termination::kCompleted, "completed"},
      {Termination::kFailed, "failed"},
      {Termination::kCancelled, "cancelled"},
  };
};

struct RunSummary {
  int iterations = 0;  ///< completed iterations
  Termination termination = Termination::kCompleted;
  std::string failure;  ///< "iteration K: why" when failed
  IterationReport last;
  double seconds = 0;
  bool failed() const { return termination == Termination::kFailed; }
};

/// A state whose DOG residual exceeds this (mesh units: a tenth of a grid edge), or whose objective
/// is not finite, has diverged: the iteration that reached it counts as failed.
constexpr double kDivergedDogResidual = 0.1;

/// Whether a state's DOG residual and stitching gap meet the final constraint tolerance (the last
/// iteration's), with the slack of twice the tolerance that rounding in the restoration leaves.
bool within_final_tolerance(const Diagnostics& d, double final_constraint_tolerance);

/// Iteration `iteration` (1-based) of a run: one iteration of the mode on x with the targets of its
/// scenario time, then the diagnostics on `problem`. `iterations_left`: iterations of the run after
/// this one (0: the last, which ends on the final constraint tolerance), or
/// IterationContext::kOpenEnded. An iteration that fails or diverges (kDivergedDogResidual) is
/// reported failed with its diagnostics and leaves x as it found it.
IterationReport run_iteration(Mode& mode, DogProblem& problem, const Scenario& scenario, Dofs& x,
                              int iteration, int iterations_left);

/// Called before iteration k (1-based) with the state x: a mode to compute the run from k on (a
/// mode switch), or nullptr to keep the current one. The returned mode must stay alive until the
/// run ends or the next switch.
using ModeSchedule = std::function<Mode*(int iteration, const Dofs& x)>;

/// Runs iterations 1 .. scenario.iterations + scenario.hold from x (updated). `problem` is the fine
/// problem the diagnostics are measured on (its targets follow the scenario too). Stops at the
/// first failed or diverged iteration (x keeps the last good state) or when `cancel` becomes true.
/// `schedule` may switch modes during the run.
RunSummary run_scenario(Mode& mode, DogProblem& problem, const Scenario& scenario, Dofs& x,
                        const std::vector<RunObserver*>& observers,
                        const std::atomic<bool>* cancel = nullptr,
                        const ModeSchedule& schedule = {});

}  // namespace sdog
