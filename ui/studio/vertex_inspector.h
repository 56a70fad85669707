#pragma once
// The inspector's text for a fine vertex: index, patch, vertex class, type and twin in the coarse
// mesh (the fine/coarse map), position and residuals in the shown state.
#include <QString>

#include "geometry/mesh/dog_model.h"
#include "ui/vis/scene_state.h"

namespace sdog::studio {

/// Rich text (a small HTML table); throws std::out_of_range for a vertex that does not exist.
QString describe_vertex(const DogModel& model, const vis::SceneState& state, int vertex);

}  // namespace sdog::studio
