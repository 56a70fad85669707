#pragma once
// A patch stepped by Ceres with an augmented Lagrangian (ceres_patch_solver.h), behind the
// PatchStepper interface: the patch modes choose it without including Ceres.
#include <memory>
#include <string>
#include <vector>

#include "geometry/mesh/dog_mesh.h"
#include "solver/patches/ceres/ceres_patch_options.h"
#include "solver/patches/patch_stepper.h"
#include "solver/patches/patch_term.h"
#include "solver/terms/weighted_term.h"

namespace sdog {

/// The version of the Ceres the program was built with.
std::string ceres_version();

/// The terms, `dog` and the coupling's frozen state must outlive the stepper.
std::unique_ptr<PatchStepper> make_ceres_patch(const DogMesh& mesh, int patch,
                                               const std::vector<WeightedTerm>& terms,
                                               const Term& dog, const CeresPatchOptions& options,
                                               const PatchCoupling& coupling = {});

}  // namespace sdog
