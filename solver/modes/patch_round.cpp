#include "solver/modes/patch_round.h"

#include "solver/sqp/blas_threads.h"

namespace sdog {

bool step_patch_round(std::vector<std::unique_ptr<PatchStepper>>& patches, Dofs& x, bool last,
                      StepReport& report, const std::vector<char>* active) {
  // Parallelism comes from the patches (TBB): the factorisations inside run on one BLAS thread
  // each (two patch threads with two BLAS threads each oversubscribe two cores).
  set_blas_threads(1);
  const std::vector<PatchReport> round = step_patches(patches, x, last, active);
  const bool first = report.patches.empty();
  if (first) report.patches = round;
  for (size_t i = 0; i < round.size(); ++i) {
    const PatchReport& p = round[i];
    if (!first) {
      PatchReport& sum = report.patches[i];
      sum.ms += p.ms;
      sum.outer += p.outer;
      sum.work += p.work;
      sum.objective = p.objective;
      sum.dog_max = p.dog_max;
      sum.converged = p.converged;
    }
    report.work += p.work;
    if (!p.converged && !report.failed) {
      report.failed = true;
      report.failure = "the step of patch " + std::to_string(p.patch) + " failed";
    }
  }
  if (!x.allFinite()) {
    report.failed = true;
    report.failure = "a patch solve produced NaN or infinity";
  }
  return !report.failed;
}

}  // namespace sdog
