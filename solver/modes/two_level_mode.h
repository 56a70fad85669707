#pragma once
// The two-level mode ("twolevel", this project's design): block Jacobi over the fine patches with a
// coarse-grid correction. One iteration =
//   1. coarse step: one standard iteration on the coarse DOG (coarse_level.h), its link vertices
//      pulled towards their fine twins (link weight);
//   2. correction: the fine state moves by the coarse step's displacement carried to the fine mesh,
//      x += P (c_new - c_old) (prolongation.h);
//   3. fine step: one block-Jacobi round of the fine patches in parallel (subsolvers_mode.h), which
//      restores the fine DOG constraints and settles the fine detail, the stitching and the folds.
// Concurrent coarse step (`concurrent_coarse`, the default): the coarse step of the next iteration
// runs beside this iteration's fine round, on the other core (CoarseLevel::run_beside: without link
// targets the coarse step reads nothing of the fine mesh), and the next iteration takes it: the
// same result as the three steps one after another, as listed, but the coarse step costs no wall
// time where the patches leave a core idle. With a positive link weight the coarse step reads the
// fine state, and the steps run one after another.
// `coarse_every` k > 1: the coarse step runs only in every k-th iteration and its correction is
// applied in k equal shares, one per iteration (faster iterations, a worse thesis grid:
// docs/design/rejected.md).
// Block Jacobi alone hands a drag on by one patch per iteration and lags far behind moving
// targets; the correction moves the whole sheet at once. The coarse state enters the fine problem
// only as a displacement, never as a target, so once the coarse mesh settles the fine iteration is
// plain block Jacobi, whose fixed points are stationary points of the whole fine objective (the
// standard solver's; subsolvers_mode.h). The thesis's coarse mode instead pins the fine creases to
// the coarse curves, and its fine result inherits the coarse mesh's error.
//
// Standard finish: the last `standard_finish` iterations of a run (of a known length: not in the
// studio) are standard iterations on the fine sheet (standard_mode.h, with fold retries up to
// `finish_fold_bias_cap` times the base fold-bias weight), as if the run switched to the standard
// mode there; the coarse mesh stays where it was. The last of them is an ordinary standard
// iteration and the projection onto the constraints (as the patch modes' last iteration), not the
// standard's polish. Block Jacobi converges slowly on a held state; the finish brings the result
// to the standard mode's (docs/design/modes.md).
#include <memory>

#include "geometry/mesh/dog_model.h"
#include "solver/modes/coarse_level.h"
#include "solver/modes/mode.h"
#include "solver/modes/mode_options.h"
#include "solver/modes/standard_mode.h"
#include "solver/modes/subsolvers_mode.h"

namespace sdog {

class TwoLevelMode : public Mode {
 public:
  /// The fine problem and the model must outlive the mode.
  TwoLevelMode(DogProblem& fine, const DogModel& model, const Scenario& scenario,
               const TwoLevelOptions& options, const StandardOptions& standard,
               const SubsolverOptions& subsolvers);
  ModeKind kind() const override { return ModeKind::kTwoLevel; }
  /// Within the last standard_finish iterations of a run (ctx.iterations_left) the standard
  /// finish computes the iteration.
  StepReport iterate(const IterationContext& ctx, Dofs& x) override;
  /// True once the standard finish computes the iterations.
  bool finishing() const { return finish_ != nullptr; }
  /// Restricts x to the coarse mesh (restriction.h) and restarts the coarse solver.
  void start_from(const Dofs& x) override;
  const Dofs& coarse_state() const { return coarse_.state(); }
  const Dofs* coarse_positions() const override { return &coarse_.state(); }
  const CoarseLevel& coarse_level() const { return coarse_; }

 private:
  /// Starts the standard finish when `iterations_left` is within standard_finish.
  void begin_finish_if_due(int iterations_left);
  StepReport finish_iteration(Dofs& x, bool last);
  StepReport two_level_iteration(const IterationContext& ctx, Dofs& x);
  DogProblem& problem_;
  Scenario scenario_;
  StandardOptions standard_;
  TwoLevelOptions options_;
  CoarseLevel coarse_;
  SubsolversMode fine_;
  std::unique_ptr<StandardMode> finish_;  // the standard finish, once it has begun
  int shares_left_ = 0;    // iterations still to take a share; 0: a coarse step is due
  Dofs correction_share_;  // fine displacement per iteration of the last coarse step
};

}  // namespace sdog
