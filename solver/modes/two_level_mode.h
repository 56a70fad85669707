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
// applied in k equal shares, one per iteration (docs/solver-modes.md, "A coarse step every other
// iteration": up to 1.24x faster iterations at 4_corners 81x81, worse on the thesis grid).
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
// standard's polish. Block Jacobi converges slowly on a held state: on the thesis grid 30 such
// iterations bring the geometric-mean objective ratio to the standard mode from 2.17 to 1.04
// (docs/solver-modes.md, "The two-level mode's standard finish").
#include <memory>

#include "geometry/dog_model.h"
#include "solver/modes/coarse_level.h"
#include "solver/modes/mode.h"
#include "solver/modes/standard_mode.h"
#include "solver/modes/subsolvers_mode.h"

namespace sdog {

struct TwoLevelOptions {
  /// Pull of the coarse link vertices towards their fine twins. 0 (the default): the coarse mesh
  /// runs on its own and only drives the fine one; any pull closes a feedback loop (the coarse
  /// step follows the fine motion, which the correction then adds to the fine mesh again) that
  /// made the flattening test diverge with 0.1 (docs/solver-modes.md, "The two-level mode").
  double link_weight = 0;
  /// Sharpness k of the fold bias (fold_bias.h) in the coarse step and the fine patches; the run's
  /// objective and fold test keep the standard k = 1000. At 1000 the correction tips fine fold
  /// sites across the crease's osculating plane, where the tanh is saturated and block Jacobi
  /// cannot bring them back (4_corners 41x41: 11 of 120 sites stay unfolded, fold bias 44 of an
  /// objective of 47); at 100 they keep a slope and refold. Thesis grid, final objective over the
  /// standard's: geometric mean 2.17 with 100 against 4.15 with 1000, better in 11 of 16 cases
  /// (docs/solver-modes.md, "The two-level mode").
  double fold_sharpness = 100;
  /// Iterations at the end of a run computed by the standard mode (see above); 0: none. Thesis
  /// grid, objective over the standard's (geometric mean / cases within 2% and folded / folded):
  /// 10 iterations without fold retries 1.09 / 6 / 12; 30 without 1.10 / 8 / 11 (valley 41x41
  /// ends with a site stuck across its crease); 30 with retries up to 10x 1.04 / 10 / 15
  /// (docs/solver-modes.md, "The two-level mode's standard finish").
  int standard_finish = 30;
  /// The finish's fold retries (standard_mode.h) raise the fold-bias weight at most to this
  /// multiple of its base weight; 1: no retries. The standard mode's 1e14 wrecked sheets handed
  /// over with unfolded sites (valley 61x61: objective 6.4e9 in the first finishing iteration).
  double finish_fold_bias_cap = 10;
  /// The next iteration's coarse step beside this one's fine round (see above); the results do
  /// not depend on it.
  bool concurrent_coarse = true;
  /// A coarse step every this many iterations (>= 1): its displacement, carried to the fine mesh,
  /// is spread evenly over those iterations (a share in each), so the coarse mesh takes one SQP
  /// step per `coarse_every` increments of the scenario and the coarse work per iteration falls by
  /// that factor.
  int coarse_every = 1;
  std::string validate() const;
};

class TwoLevelMode : public Mode {
 public:
  /// The fine problem and the model must outlive the mode.
  TwoLevelMode(DogProblem& fine, const DogModel& model, const Scenario& scenario, const TwoLevelOptions& options,
               const StandardOptions& standard, const SubsolverOptions& subsolvers);
  const char* name() const override { return "twolevel"; }
  void set_time(double t) override;
  StepReport iterate(Dofs& x, bool last) override;
  /// Within the last standard_finish iterations of a run the standard finish takes over.
  void set_iterations_left(int left) override;
  void set_next_time(std::optional<double> t) override { next_time_ = t; }
  /// True once the standard finish computes the iterations.
  bool finishing() const { return finish_ != nullptr; }
  /// Restricts x to the coarse mesh (restriction.h) and restarts the coarse solver.
  void start_from(const Dofs& x) override;
  const Dofs& coarse_state() const { return coarse_.state(); }
  const Dofs* coarse_positions() const override { return &coarse_.state(); }
  const CoarseLevel& coarse_level() const { return coarse_; }

 private:
  StepReport finish_iteration(Dofs& x, bool last);
  DogProblem& problem_;
  Scenario scenario_;
  StandardOptions standard_;
  TwoLevelOptions options_;
  CoarseLevel coarse_;
  SubsolversMode fine_;
  std::unique_ptr<StandardMode> finish_;  // the standard finish, once it has begun
  int iterations_left_ = kOpenEnded;      // after the current iteration
  std::optional<double> next_time_;       // of the next iteration, when the run has one
  int shares_left_ = 0;                   // iterations still to take a share; 0: a coarse step is due
  Dofs correction_share_;                 // fine displacement per iteration of the last coarse step
};

}  // namespace sdog
