#include "solver/modes/patch_round.h"

#include "solver/sqp/blas_threads.h"

namespace sdog {

bool step_patch_round(std::vector<std::unique_ptr<PatchStepper>>& patches, Dofs& x, bool last,
                      StepReport& report, const std::vector<char>* active) {
  // Parallelism comes from the patches (TBB): the factorisations inside run on one BLAS thread
  // each (measured at 81x81: 2 patch threads x 2 BLAS threads oversubscribe 2 cores, 159 ms per
  // iteration; with 1 BLAS thread 73 ms).
  set_blas_threads(1);
  const std::vector<PatchReport> round = step_patches(patches, x, last, active);
  const bool first = report.patches.empty();
  if (first) report.patches = round;
  for (size_t i = 0; i < round.size(); ++i) {
    const PatchReport& p = round[i];
    if (!first) {
      PatchReport& sum = report.patches[i];
      sum.ms += p.ms;
      sum.linear_ms += p.linear_ms;
      sum.outer += p.outer;
      sum.inner += p.inner;
      sum.factorizations += p.factorizations;
      sum.objective = p.objective;
      sum.dog_max = p.dog_max;
      sum.converged = p.converged;
    }
    report.sqp_steps += p.inner;
    report.factor_ms += p.linear_ms;
    report.factorizations += p.factorizations;
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
