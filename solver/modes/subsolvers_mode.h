#pragma once
// The thesis's "subsolvers" mode (block Jacobi over patches): every patch is its own problem
// (patch_solver.h: Ceres, DOG constraints by an augmented Lagrangian) with, for every stitching
// pair, an edge-point target on its own copy at the other copy's position from the previous
// iterate, with the whole stitching weight (so that the standard solver's end state is a fixed
// point of the iteration). All patches are solved in parallel (TBB), then the targets are
// refreshed.
//
// The fold bias and dihedral angle constraints couple two patches: each patch keeps their blocks
// with the other patch's vertices frozen at the state the round started from (patch_term.h), so a
// fixed point of the iteration is a stationary point of the whole objective's fold and angle parts.
//
// The run's last iteration is an ordinary round followed by a projection of the whole sheet onto
// the DOG constraints to the final tolerance (final_projection.h), not a polishing patch round.
#include <memory>

#include "solver/modes/final_projection.h"
#include "solver/modes/mode.h"
#include "solver/modes/mode_options.h"
#include "solver/patches/patch_stepper.h"
#include "solver/problem/dog_problem.h"
#include "solver/terms/fold_bias.h"
#include "solver/terms/linear_point_term.h"

namespace sdog {

class SubsolversMode : public Mode {
 public:
  /// The problem must outlive the mode; the scenario is installed into it.
  SubsolversMode(DogProblem& problem, const Scenario& scenario, const SubsolverOptions& options,
                 const SqpOptions& sqp);
  ModeKind kind() const override { return ModeKind::kSubsolvers; }
  StepReport iterate(const IterationContext& ctx, Dofs& x) override;
  /// Sets the targets of scenario time t.
  void set_time(double t);
  /// One iteration at the targets of the last set_time.
  StepReport round(Dofs& x, bool last);

 private:
  void refresh_targets(const Dofs& x);
  DogProblem& problem_;
  Scenario scenario_;
  SubsolverOptions options_;
  std::unique_ptr<FoldBiasTerm>
      fold_bias_;  // when options_.fold_sharpness differs from the problem's
  LinearPointTerm targets_{"stitch_targets"};  // one block per copy and stitching pair
  std::vector<EdgePoint> other_;               // per block: the copy whose position is the target
  Dofs frozen_;                                // the state the round started from
  std::vector<std::unique_ptr<PatchStepper>> patches_;
  std::vector<std::vector<char>> sweeps_;  // the patches stepping in each round of an iteration
  FinalProjection projection_;             // the last iteration's (final_projection.h)
};

}  // namespace sdog
