#pragma once
// The coarse DOG of the two-resolution modes (coarse, twolevel): the fine scenario's position
// targets carried to the coarse mesh, stepped by the standard solver, its link vertices pulled
// towards their fine twins.
//
// A position target on a fine link vertex becomes a position target on its coarse twin. A target on
// any other fine vertex becomes a target on the weighted sum of coarse vertices the prolongation
// gives that vertex (prolongation.h: the coarse edge midpoint, quad centre, ...) with the position
// weight: the coarse mesh is asked to place the point where the fine vertex would be carried.
// An angle constraint at a fine crease point that has a coarse twin (a crease point at the same
// flat position) becomes the same dihedral angle constraint at the twin; the others act on the fine
// mesh only. A run that starts from a given fine state (scenario.initial) or takes over from
// another mode starts the coarse mesh from its restriction, with the coarse folding mode off when
// the restriction is not folded (see start_from).
//
// Stepping ahead: without link targets (link weight 0, the default) a coarse step reads nothing of
// the fine mesh, only the coarse state and the scenario's targets, so the step of iteration k + 1
// can be computed during iteration k, beside its fine round (run_beside), and iteration k + 1
// takes it instead of computing it: the same result as one after the other, bit for bit, since
// the coarse step always factorises on one BLAS thread (blas_threads.h). The coarse step then
// costs no wall time where the fine round leaves a core idle.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "solver/modes/mode_kind.h"
#include "solver/modes/standard_mode.h"
#include "solver/multilevel/prolongation.h"
#include "solver/problem/dog_problem.h"
#include "solver/problem/scenario.h"

namespace sdog {

class CoarseLevel {
 public:
  /// `link_weight` 0: the coarse mesh is not pulled towards the fine one. `mode` names the mode
  /// in usage errors; `fold_sharpness` that of the coarse fold bias (fold_bias.h). The model must
  /// outlive the level.
  CoarseLevel(const DogProblem& fine, const DogModel& model, const Scenario& scenario,
              double link_weight, const StandardOptions& standard, ModeKind mode,
              double fold_sharpness = kFoldSharpness);
  ~CoarseLevel();
  /// Throws the UsageError the constructor would throw: the model has no coarse mesh.
  static void check_usable(const DogModel& model, ModeKind mode);

  void set_time(double t);
  /// One standard iteration on the coarse mesh, with the link targets at the fine twins in `fine_x`
  /// first (when the link weight is positive). Never a polishing iteration: the coarse mesh only
  /// drives the fine one, whose last iteration ends with the final projection (final_projection.h).
  /// The step computed ahead for this time (run_beside) is taken instead when there is one.
  StepReport step(const Dofs& fine_x);
  /// Runs `work` and, when `next_time` is given and the level can step ahead (link weight 0), the
  /// coarse step of the next iteration (targets at `next_time`) beside it, in parallel (TBB). The
  /// state stays that of this iteration until the next step() takes the step. `work` must not
  /// touch this level.
  void run_beside(const std::function<void()>& work, std::optional<double> next_time);
  bool can_step_ahead() const { return link_weight_ == 0; }
  /// Steps taken from run_beside so far (tests).
  int steps_taken_ahead() const { return taken_ahead_; }

  /// The coarse state for a fine state that did not come from this level (restriction.h), and a
  /// fresh start of the coarse solver.
  void start_from(const Dofs& fine_x);

  const Dofs& state() const { return x_; }
  /// The coarse problem (its targets are those of the last set_time).
  const DogProblem& problem() const { return *problem_; }
  /// Also drops a step computed ahead (it started from the state replaced).
  void set_state(const Dofs& x) {
    x_ = x;
    ahead_.reset();
  }
  const Prolongation& prolongation() const { return prolongation_; }
  /// Link pairs: fine vertex links()[i].first has coarse twin links()[i].second.
  const std::vector<std::pair<int, int>>& links() const { return links_; }

 private:
  const DogModel& model_;
  double link_weight_;
  Prolongation prolongation_;
  std::unique_ptr<DogProblem> problem_;
  std::unique_ptr<StandardMode> mode_;
  Dofs x_;
  double t_ = 0;  // scenario time of the targets
  struct Ahead {
    double t;  // the time it was computed for
    Dofs x;
    StepReport report;
  };
  std::optional<Ahead> ahead_;  // the next iteration's step, computed by run_beside
  int taken_ahead_ = 0;
  std::vector<std::pair<int, int>> links_;
  std::vector<PositionConstraint> carried_;  // targets on fine-only vertices: blocks of edge_points
};

}  // namespace sdog
