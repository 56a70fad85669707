#pragma once
// When the standard mode settles, and which fold it keeps (standard_mode.h). A folded sheet has
// several stationary states a few percent apart in objective, and which one a run reaches depends
// on the path its targets took. Once the targets have come to rest and the state has converged,
// the mode folds the sheet again from the origin (the state the run started from) straight to the
// resting targets and keeps the better of the two folds. A run whose targets moved once from the
// origin (set at once) has taken that straight path already and does not settle; a target that
// moves again makes settling due again.
#include <optional>

#include "solver/terms/term.h"

namespace sdog {

/// What settling did in an iteration, as StepReport::stage and the run log's `settling` column
/// say it: the straight fold took an iteration (the state is unchanged), or it ended and the run's
/// own fold was kept or replaced.
namespace settling_stage {
inline constexpr const char* kRunning = "running";
inline constexpr const char* kKept = "kept";
inline constexpr const char* kReplaced = "replaced";
}  // namespace settling_stage

class SettlingPlan {
 public:
  /// Iterations of the straight fold at most; a settling that has not converged by then is dropped.
  static constexpr int kMaxIterations = 200;
  /// `on`: StandardOptions::settle. `origin`: the state the run started from when the mode's first
  /// iteration does not start there (the studio makes a new mode after every edit); without it the
  /// first iteration's state is the origin.
  SettlingPlan(bool on, std::optional<Dofs> origin);
  /// Before every converging iteration, at x.
  void begin_iteration(const Dofs& x);
  /// The requested targets changed: settling is due again once they rest.
  void new_goal();
  /// The targets rest and the state has converged: whether the straight fold is still to be made.
  bool wanted() const;
  /// The state the straight fold starts from (after the first begin_iteration).
  const Dofs& origin() const { return *origin_; }
  /// The straight fold ended (kept or replaced, or dropped): settling is done for these targets.
  void done() { settled_ = true; }
  /// A fresh start of the mode at another state (Mode::start_from): the origin is forgotten unless
  /// it was given.
  void restart();

 private:
  bool on_;
  std::optional<Dofs> origin_;
  bool origin_given_;
  bool away_from_origin_ = false;  ///< the first iteration started elsewhere than at the origin
  int goals_ = 0;                  ///< distinct target sets the mode was asked for
  bool settled_ = false;           ///< settling is done for the last ones
};

/// A finished fold as settling compares it (both projected to the final constraint tolerance).
struct SettledFold {
  bool folded = false;
  int against = 0;  ///< fold sites bent against their angle targets (AngleAgreement::all_against)
  double objective = 0;
};

/// Whether the straight fold replaces the run's fold: when it is folded and bends fewer fold sites
/// against their angle targets; with as many, when the run's fold is unfolded or its objective is
/// higher by more than `margin`.
bool straight_fold_wins(const SettledFold& run, const SettledFold& straight, double margin);

}  // namespace sdog
