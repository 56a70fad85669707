#pragma once
// One round of a multi-patch mode (subsolvers, ADMM): every patch steps from x in parallel
// (patch_stepper.h), and the patch reports are folded into the iteration's report.
#include <memory>
#include <vector>

#include "solver/modes/mode.h"
#include "solver/patches/patch_stepper.h"

namespace sdog {

/// Steps every patch from x (with `active`: only the patches marked there) and adds the round to
/// `report`: one entry per patch in report.patches (over several rounds of one iteration: times
/// and work summed; objective, DOG residual and convergence of the latest round), and the work
/// of every patch in report.work (its factor_ms is then CPU time, not wall time). Returns false
/// and marks the report failed when a patch step failed or produced NaN or infinity; the caller
/// rolls x back.
bool step_patch_round(std::vector<std::unique_ptr<PatchStepper>>& patches, Dofs& x, bool last,
                      StepReport& report, const std::vector<char>* active = nullptr);

}  // namespace sdog
