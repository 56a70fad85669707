#pragma once
// The thesis's coarse mode ("coarse guess"), one iteration =
//   1. coarse step: one standard-solver iteration on the coarse DOG, position constraints moved
//      to the coarse twins of their (link) vertices, coarse link vertices pulled towards their
//      fine twins (link weight; on both sides, unlike the reference);
//   2. coarse to fine: every coarse crease curve is interpolated at the fine crease points (cubic
//      Lagrange interpolation in flat arc length, curve_interpolation.h), and both copies of each
//      fine crease point get that position as an edge-point target (weight 0.5 x stitching: it
//      replaces stitching on the fine side);
//   3. fine step: every fine patch steps on its own (patch_stepper.h, in parallel) with its
//      bending, isometry, positions, the crease targets and link targets at the coarse twins of
//      its link vertices (link weight);
//   4. fine to coarse: the coarse link targets of the next iteration are the new fine positions
//      (off with fine_to_coarse = false).
// With `concurrent_coarse` (the default) the coarse step of the next iteration runs beside the
// fine round (CoarseLevel::run_beside: without link targets it reads nothing of the fine mesh),
// with the same result as the steps one after another. The coarse mesh and the carrying of position
// targets to it: coarse_level.h.
#include <memory>

#include "geometry/mesh/dog_model.h"
#include "solver/modes/coarse_level.h"
#include "solver/modes/final_projection.h"
#include "solver/modes/mode.h"
#include "solver/modes/mode_options.h"
#include "solver/modes/standard_mode.h"
#include "solver/multilevel/curve_interpolation.h"
#include "solver/patches/patch_stepper.h"
#include "solver/problem/dog_problem.h"

namespace sdog {

class CoarseMode : public Mode {
 public:
  /// The fine problem and the model must outlive the mode; the scenario is installed into the
  /// fine problem and mapped to the coarse one.
  CoarseMode(DogProblem& fine, const DogModel& model, const Scenario& scenario,
             const CoarseOptions& options, const StandardOptions& standard);
  ~CoarseMode() override;
  ModeKind kind() const override { return ModeKind::kCoarse; }
  StepReport iterate(const IterationContext& ctx, Dofs& x) override;
  /// Restricts x to the coarse mesh (restriction.h) and restarts the coarse solver.
  void start_from(const Dofs& x) override;
  const Dofs& coarse_state() const;
  const Dofs* coarse_positions() const override { return &coarse_state(); }
  const CoarseLevel& coarse_level() const { return *coarse_; }

 private:
  void set_time(double t);
  void set_crease_targets();
  void set_fine_link_targets();
  DogProblem& fine_;
  const DogModel& model_;
  Scenario scenario_;
  CoarseOptions options_;
  std::unique_ptr<CoarseLevel> coarse_;
  LinearPointTerm crease_targets_{"crease_targets"};  // per fine crease point copy
  std::vector<CurveStencil> crease_stencils_;         // per block of crease_targets_
  Dofs frozen_;  // the fine state before the patch step: the other side of cross-patch blocks
  std::vector<std::unique_ptr<PatchStepper>> patches_;
  std::unique_ptr<FinalProjection> projection_;  // the last iteration's (final_projection.h)
};

}  // namespace sdog
