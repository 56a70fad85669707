#pragma once
// One step of one patch in the multi-patch modes, whatever solves it: Ceres with an augmented
// Lagrangian (patch_solver.h) or the standard solver's SQP iteration on the patch's blocks
// (patch_sqp.h). Patch steps are independent and run in parallel.
#include <memory>
#include <vector>

#include "solver/patches/patch_report.h"
#include "solver/terms/term.h"

namespace sdog {

class PatchStepper {
 public:
  virtual ~PatchStepper() = default;
  virtual int patch() const = 0;
  /// The patch's vertex count: the larger patches start first (step_patches).
  virtual int vertex_count() const = 0;
  /// One step from x; writes the patch's vertices into x and nothing else. `last`: the run's last
  /// iteration (final constraint tolerance).
  virtual PatchReport step(Dofs& x, bool last) = 0;
  /// Changes the weight of the objective term `index` (as passed at construction).
  virtual void set_weight(size_t index, double weight) = 0;
};

/// Steps every patch from x in parallel (TBB), writing each patch's vertices into x. Reports in
/// patch order, with start times and worker threads; the result does not depend on the thread
/// count. Each thread takes the largest patch not yet started (greedy list scheduling), so the
/// largest patch starts at once and small ones fill the gaps, also around work that runs beside
/// the round (the two-level mode's coarse step). With `active`, only the patches marked there
/// step (the others report a converged step that took no time and leave their vertices as they
/// are).
std::vector<PatchReport> step_patches(std::vector<std::unique_ptr<PatchStepper>>& patches, Dofs& x,
                                      bool last, const std::vector<char>* active = nullptr);

}  // namespace sdog
