#pragma once
// The standard mode: the global SQP solver (sqp_solver.h) on the whole fine DOG, in folding mode
// by default: after an iteration that leaves the sheet unfolded (check_folded), x is rolled back,
// the fold-bias weight multiplied by 10 and the iteration solved again, up to max_fold_bias;
// after a folded iteration the weight returns to its base value. When no weight folds the sheet,
// the iteration keeps its attempt with the fewest unfolded sites (among those meeting the
// constraints as well as the first attempt) and the base weight. Off for scenarios that unfold
// (Scenario::keeps_folds false).
//
// Exact stitching (the default): the stitching of the crease points is a hard constraint beside
// the DOG constraints (hard_constraints.h), so the two copies of every crease point coincide to
// the constraint tolerance after every iteration.
//
// Converging iterations (StandardOptions::converge, the default). An iteration whose targets hold
// takes steps until a full step would no longer lower the objective noticeably (SqpSolver::
// converge), at most max_iteration_steps; once converged, held iterations cost nothing (no
// factorisation) until a target moves. Targets that move are followed by continuation: from the
// targets the state meets towards the requested ones, in sub-steps of at most max_target_step of
// the sheet's size, each one SQP step and a restoration that stops once the constraints are
// within substep_constraint_tolerance (the iteration's state is restored to the constraint
// tolerance once, at its end: most sub-steps then need no factorisation of their own for the
// restoration). A sub-step is kept when its line search
// kept at least substep_step_length of the full step, or when it is short (at most 1/4 of the
// cap), and the next one is then twice as long; else it is rolled back and halved, down to 1/1024
// of the remaining motion. An iteration takes at most max_iteration_steps sub-steps and reports how
// far along the motion it got (StepReport::target_fraction); the next one goes on from there.
// Targets that move no further than a short sub-step take the thesis's iteration, at its cost. The
// line search of converging steps turns to the fallback merit penalty after the full step
// (SqpSolver::converge). A target the sheet cannot reach (off the sheet, or asking
// for stretching) leaves the sheet as close as its constraints allow: the targets are soft, and
// the iteration converges there. Held iterations that keep taking steps without lowering the
// objective (steps that cycle, or a crease that unfolds in every iteration and is refolded by the
// fold-bias retry) count as converged once kHeldWithoutProgress of them in a row have not lowered
// it by more than converged_decrease below its lowest value since the targets last moved. In a
// converging iteration a raised fold bias returns to its base weight at the iteration's end, and
// once an escalation has ended unfolded the iteration's later sub-steps take none. The last
// iteration of a run projects x to the final constraint tolerance (finish()).
//
// Settling (StandardOptions::settle, with converging iterations; settling_plan.h). Once the
// targets have come to rest and the state has converged, the mode also folds the sheet from the
// origin straight to the resting targets, one iteration of its own per held iteration of the run;
// once that has converged, both states are projected to the final constraint tolerance (finish(),
// which changes their objectives by different amounts) and the better fold is kept, there. The
// held iterations report the shape converged only once that is done; a target that moves again
// drops a settling in progress.
//
// The policies are small classes of their own: the fold-bias ladder (fold_bias_ladder.h), the
// sub-step sizes of continuation (substep_schedule.h), convergence of held iterations without
// progress (held_progress.h) and settling (settling_plan.h).
#include <memory>
#include <optional>
#include <utility>

#include "solver/modes/fold_bias_ladder.h"
#include "solver/modes/hard_constraints.h"
#include "solver/modes/held_progress.h"
#include "solver/modes/mode.h"
#include "solver/modes/mode_options.h"
#include "solver/modes/settling_plan.h"
#include "solver/modes/substep_schedule.h"
#include "solver/problem/dog_problem.h"
#include "solver/problem/targets.h"

namespace sdog {

class SqpSolver;

class StandardMode : public Mode {
 public:
  /// The problem must outlive the mode; the scenario is installed into it. `origin`: the state the
  /// run started from when this mode's first iteration does not start there (settling_plan.h).
  StandardMode(DogProblem& problem, const Scenario& scenario, const StandardOptions& options,
               std::optional<Dofs> origin = std::nullopt);
  ~StandardMode() override;
  ModeKind kind() const override { return ModeKind::kStandard; }
  StepReport iterate(const IterationContext& ctx, Dofs& x) override;
  /// Zero multipliers and the base fold bias: a fresh start from x. With exact stitching the next
  /// iteration first restores the constraints (a state from a patch mode has gaps at the creases).
  void start_from(const Dofs& x) override;

  /// Sets the targets of scenario time t.
  void set_time(double t);
  /// One iteration at the targets of the last set_time (`last`: the run's last iteration).
  StepReport step(Dofs& x, bool last);
  /// Folding mode on (fold bias at its base weight, fold check and retries) or off (no fold bias).
  void set_folding(bool on);
  SqpSolver& sqp() { return *sqp_; }

 private:
  /// SQP steps of the current targets with the fold check and its retries (folding mode): the
  /// thesis's iteration (max_steps 0: sqp.max_steps steps, polished when `last`) or at most
  /// max_steps steps towards convergence.
  StepReport attempt(Dofs& x, bool last, int max_steps);
  /// Every fold site folded at x (true when folding mode is off).
  bool folded(const Dofs& x) const;
  /// A converging iteration (continuation towards the installed targets).
  StepReport converge(Dofs& x, bool last);
  /// Continuation sub-steps from reached_ towards `goal`, `distance` away (moved targets).
  StepReport follow(Dofs& x, const Targets& goal, double distance);
  /// One iteration of the straight fold from origin_ (settling), and at its end the choice of the
  /// lower state; report.converged becomes true when the settling is done.
  void settle(Dofs& x, StepReport& report);
  /// The last converging iteration's end: x projected to the final constraint tolerance, again
  /// with a raised fold bias while that leaves a fold site unfolded; report.folded says whether x
  /// ends folded.
  void finish(Dofs& x, StepReport& report);
  /// After a last iteration that ended unfolded or failed from a converged folded state: that
  /// state (positions and multipliers) finished without the iteration's steps, kept when it ends
  /// folded.
  void finish_folded(Dofs& x, const std::pair<Dofs, Eigen::VectorXd>& converged,
                     StepReport& report);
  /// |c|_inf of x with the iterations' constraint scale (finish() runs with the final one).
  double iteration_residual(const Dofs& x);
  /// x projected to the final constraint tolerance (at the stitching rows' final scale).
  void project(Dofs& x, StepReport& report);
  /// One SQP solve, its work added to `report`; false when it failed.
  bool solve(Dofs& x, bool last, int max_steps, StepReport& report, double& constraint_max);
  /// Retries of an iteration that left the sheet unfolded (x0, lambda0: where it started).
  void escalate_fold_bias(Dofs& x, const Dofs& x0, const Eigen::VectorXd& lambda0, bool last,
                          int max_steps, int violations, double constraint_max, StepReport& report);
  /// The next rung of the fold-bias ladder, a retry counted in `report`; false at the top.
  bool raise_fold_bias(double& weight, StepReport& report);
  DogProblem& problem_;
  Scenario scenario_;
  StandardOptions options_;
  HardConstraints constraints_;
  std::unique_ptr<SqpSolver> sqp_;
  FoldBiasLadder ladder_;
  SubstepSchedule substeps_;
  HeldProgress held_;
  SettlingPlan settling_;
  bool restore_first_ = false;
  std::optional<Targets> reached_;  ///< the targets the state was last solved for
  bool converged_ = false;          ///< x is converged for reached_
  std::optional<Targets> goal_;     ///< the targets last requested
  struct StraightFold;
  std::unique_ptr<StraightFold> straight_;  ///< settling's straight fold in progress
  double constraint_max_ = 0;               ///< after the last solve
  /// The largest continuation sub-step: max_target_step of the largest side of the rest state's
  /// bounding box, max_angle_step.
  TargetSteps steps_;
};

}  // namespace sdog
