#pragma once
// The VTK files of a meshed crease pattern (all in mesh units, z = 0, so they overlay in ParaView):
//   fine.vtu     fine DOG; point arrays vertex_type, patch, partner, vertex_class; cell array patch
//   coarse.vtu   coarse DOG, same arrays
//   creases.vtp  crease polylines through the fine crease points; cell arrays crease, closed,
//                assignment (0 unassigned, 1 mountain, 2 valley, 3 flat) and angle (the drawing's
//                fold angle in degrees, positive for valleys; NaN where the drawing gives none)
//   pattern.vtp  the curves as drawn; cell arrays kind (0 boundary, 1 crease), index, assignment
#include <string>

#include "base/atomic_output.h"
#include "geometry/mesh/dog_model.h"

namespace sdog::vis {

/// Writes the files above into the output set (coarse.vtu only when the model has a coarse mesh).
void write_model_files(const DogModel& model, OutputSet& out);

}  // namespace sdog::vis
