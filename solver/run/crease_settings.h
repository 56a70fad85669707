#pragma once
// Creases named by the run configuration: by index among the cleaned creases (the order
// `sdog mesh` lists them in) or by the SVG element id that drew them, and the assignments and fold
// angles the configuration sets on them over the drawing's.
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "solver/run/run_config.h"

namespace sdog {

/// The cleaned creases named by `curve` (one index) or `id` (every crease its element drew).
/// Throws InputError naming `path` when there is no such crease.
std::vector<int> named_creases(const DogMesh& mesh, const std::optional<int>& curve,
                               const std::optional<std::string>& id, const std::string& path);

/// Throws InputError naming `path` when curve k of `mesh` is a slit or a seam (crease_pattern.h),
/// which do not fold.
void check_foldable(const DogMesh& mesh, int k, const std::string& path);

/// Sets each setting's assignment and angle on its creases, in the cleaned pattern and in the fine
/// and coarse stitching curves. An assignment other than mountain or valley drops the angle; an
/// angle alone keeps the assignment. Throws InputError naming the setting for a slit or a seam
/// (crease_pattern.h), which do not fold.
void apply_crease_settings(const std::vector<CreaseSetting>& settings, DogModel& model);

}  // namespace sdog
