#pragma once
// The options of the solver modes and their option tables (base/option_table.h). Options only:
// the Qt settings panel and the configuration layer include this without the solvers.
#include <string>

#include "base/enum_names.h"
#include "base/option_table.h"
#include "solver/patches/ceres/ceres_patch_options.h"
#include "solver/sqp/sqp_options.h"

namespace sdog {

/// How the two copies of a crease point are held together: as hard constraints beside the DOG
/// constraints (kExact) or by the soft stitching term alone (kSoft, the thesis).
enum class Stitching { kExact, kSoft };
template <>
struct EnumNames<Stitching> {
  static constexpr const char* noun = "stitching";
  static constexpr EnumName<Stitching> rows[] = {
      {Stitching::kExact, "exact"},
      {Stitching::kSoft, "soft"},
  };
};

/// The standard mode (standard_mode.h) and the standard iterations of the other modes.
struct StandardOptions {
  SqpOptions sqp;
  bool folding = true;         ///< fold check and fold-bias escalation (standard_mode.h)
  double max_fold_bias = 1e6;  ///< the escalation stops at this weight (the thesis: 1e14)
  /// Converging iterations (standard_mode.h); off: sqp.max_steps steps per iteration (the thesis).
  bool converge = true;
  /// SQP steps of a converging iteration at most: steps towards convergence when the targets
  /// hold, continuation sub-steps (kept or not) when they moved.
  int max_iteration_steps = 10;
  /// A continuation sub-step moves a target at most this fraction of the sheet's size.
  double max_target_step = 0.02;
  /// A continuation sub-step changes a dihedral-angle target at most this much (degrees; where the
  /// crease crosses its grid edge at right angles, more where it crosses obliquely, as the angle
  /// term weighs such sites less).
  double max_angle_step = 10;
  /// A continuation sub-step is kept when its line search kept at least this fraction of the
  /// full step.
  double substep_step_length = 0.25;
  /// Between the continuation sub-steps of one iteration, restoration stops once the DOG
  /// constraints are within this; the iteration's state is restored to sqp.constraint_tolerance
  /// at its end.
  double substep_constraint_tolerance = 0.02;
  /// Once the targets have come to rest and the state has converged, a converging run also folds
  /// the sheet from the state it started from straight to those targets and keeps whichever of
  /// the two converged folds has the lower objective (standard_mode.h).
  bool settle = true;
  Stitching stitching = Stitching::kExact;
  /// BLAS threads of the factorisations (blas_threads.h); 0: default_blas_threads(). The coarse
  /// step of the two-resolution modes, which may run beside the patch solves, uses 1
  /// (coarse_level.h).
  int blas_threads = 0;
  std::string validate() const;
};

/// How a patch step is solved: the SQP solver on the patch (patch_sqp.h) or Ceres with an
/// augmented Lagrangian (patches/ceres/ceres_patch.h).
enum class PatchBackend { kSqp, kCeres };
/// kJacobi: every patch steps at once from the same state; kColours: the patch graph's colours
/// (patch_colouring.h) step one after another, each from the state the previous left.
enum class PatchSweep { kJacobi, kColours };
template <>
struct EnumNames<PatchBackend> {
  static constexpr const char* noun = "patch backend";
  static constexpr EnumName<PatchBackend> rows[] = {
      {PatchBackend::kSqp, "sqp"},
      {PatchBackend::kCeres, "ceres"},
  };
};
template <>
struct EnumNames<PatchSweep> {
  static constexpr const char* noun = "patch sweep";
  static constexpr EnumName<PatchSweep> rows[] = {
      {PatchSweep::kJacobi, "jacobi"},
      {PatchSweep::kColours, "colours"},
  };
};

/// The per-patch steps of the patch modes (subsolvers, twolevel).
struct SubsolverOptions {
  PatchBackend backend = PatchBackend::kSqp;
  PatchSweep sweep = PatchSweep::kJacobi;
  CeresPatchOptions patch;  ///< of the Ceres backend (the SQP backend uses the standard options)
  /// Sharpness k of the patches' fold-bias term (fold_bias.h); 0: the problem's. The run's
  /// objective and fold test stay those of the problem. Set by the two-level mode.
  double fold_sharpness = 0;
  std::string validate() const;
};

/// The coarse mode (coarse_mode.h).
struct CoarseOptions {
  /// Link targets between fine and coarse twins (the thesis's ftc_weight, 0.1 there); 0: the fine
  /// mesh follows the coarse one through the crease targets only (docs/design/rejected.md).
  double link_weight = 0;
  bool fine_to_coarse = true;  ///< the coarse link vertices are pulled towards their fine twins
  bool prolongate = false;  ///< start each fine step from the coarse state carried to the fine mesh
  /// The next iteration's coarse step beside this one's fine round (coarse_level.h); the results
  /// do not depend on it. Only without link targets (link weight 0).
  bool concurrent_coarse = true;
  std::string validate() const;
};

/// The two-level mode (two_level_mode.h); docs/design/modes.md gives the reasons for the defaults.
struct TwoLevelOptions {
  /// Pull of the coarse link vertices towards their fine twins; 0: the coarse mesh only drives the
  /// fine one (a pull closes a feedback loop).
  double link_weight = 0;
  /// Sharpness k of the fold bias in the coarse step and the fine patches (the run's objective and
  /// fold test keep k = 1000).
  double fold_sharpness = 100;
  /// Iterations at the end of a run (of known length) computed by the standard mode; 0: none.
  int standard_finish = 30;
  /// The finish's fold retries raise the fold-bias weight at most to this multiple of its base
  /// weight; 1: no retries.
  double finish_fold_bias_cap = 10;
  /// The next iteration's coarse step beside this one's fine round; the results do not depend on
  /// it.
  bool concurrent_coarse = true;
  /// A coarse step every this many iterations, its displacement spread evenly over them.
  int coarse_every = 1;
  std::string validate() const;
};

/// The ADMM modes (admm_mode.h).
struct AdmmOptions {
  double rho = 1;    ///< penalty of the augmented terms
  double gamma = 1;  ///< damping of the jadmm / proxjadmm multiplier update
  double p = -1;     ///< proximal weight P = p I of proxjadmm; < 0: 0.001 (N - 1), N patches
  int inner = 1;     ///< ADMM rounds per solver iteration
  std::string validate() const;
  /// p, with the default resolved for a mesh of `patches` patches.
  double proximal_weight(int patches) const;
};

/// The options of every mode (what make_mode reads).
struct ModeOptions {
  StandardOptions standard;
  SubsolverOptions subsolvers;  ///< the patch modes' per-patch solves
  CoarseOptions coarse;
  AdmmOptions admm;
  TwoLevelOptions twolevel;
};

/// The keys of the configuration's "solver" (StandardOptions with its SqpOptions),
/// "patch_solver" (SubsolverOptions with its CeresPatchOptions), "coarse", "twolevel" and "admm"
/// objects.
const OptionTable<StandardOptions>& standard_option_table();
const OptionTable<SubsolverOptions>& subsolver_option_table();
const OptionTable<CoarseOptions>& coarse_option_table();
const OptionTable<TwoLevelOptions>& twolevel_option_table();
const OptionTable<AdmmOptions>& admm_option_table();

}  // namespace sdog
