#pragma once
// The inspector's text for picked creases: index, the element that drew it (its origin), the
// assignment and the fold angle the session folds it to.
#include <QString>
#include <optional>
#include <vector>

#include "geometry/mesh/dog_model.h"

namespace sdog::studio {

/// One line per crease: "crease k  FILE:LINE: <path id=..>  mountain, 60 degrees" (rich text).
/// `folds` and `angles` are per crease curve (the session's); a mountain or valley without an
/// angle folds to `default_degrees` (the fold scenario's angle). Throws std::out_of_range for a
/// crease that does not exist.
QString describe_creases(const DogModel& model, const std::vector<Fold>& folds,
                         const std::vector<std::optional<double>>& angles, double default_degrees,
                         const std::vector<int>& creases);

/// "mountain, 60 degrees", "valley, 90 degrees (the scenario's)", "flat", "unassigned".
QString describe_assignment(Fold fold, const std::optional<double>& angle, double default_degrees);

}  // namespace sdog::studio
