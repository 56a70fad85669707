#pragma once
// What one patch step did (patch_stepper.h); carried by the iteration report of the multi-patch
// modes for per-patch times, residuals and thread-use timelines.
#include "solver/sqp/work.h"

namespace sdog {

struct PatchReport {
  int patch = -1;
  double ms = 0;         ///< wall time of the step
  double start_ms = 0;   ///< when it started, from the start of the round (timelines)
  int thread = 0;        ///< index of the TBB worker that ran it (thread use)
  double objective = 0;  ///< weighted patch objective at the end (without the augmented terms)
  double dog_max = 0;    ///< |c|_inf of the patch's DOG constraints at the end
  int outer = 0;         ///< augmented-Lagrangian updates (Ceres backend)
  /// Optimality steps (Ceres backend: Ceres iterations), factorisations and linear-algebra time
  /// (factor_ms) of the step.
  Work work;
  bool converged = false;
};

}  // namespace sdog
