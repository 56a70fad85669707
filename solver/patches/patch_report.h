#pragma once
// What one per-patch solve did (patch_solver.h); carried by the iteration report of the
// multi-patch modes for per-patch times, residuals and thread-use timelines.
namespace sdog {

struct PatchReport {
  int patch = -1;
  double ms = 0;         ///< wall time of the solve
  double linear_ms = 0;  ///< of which Ceres' linear solves (factorisations and solves)
  double start_ms = 0;   ///< when it started, from the start of solve_patches (timelines)
  int thread = 0;        ///< index of the TBB worker that ran it (thread use)
  double objective = 0;  ///< weighted patch objective at the end (without the augmented terms)
  double dog_max = 0;    ///< |c|_inf of the patch's DOG constraints at the end
  int outer = 0;         ///< augmented-Lagrangian updates
  int inner = 0;         ///< Ceres iterations in all (SQP backend: optimality steps)
  int factorizations = 0;  ///< global factorisations of the patch (SQP backend)
  bool converged = false;
};

}  // namespace sdog
