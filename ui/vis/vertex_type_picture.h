#pragma once
// The fine/coarse picture: fine mesh (left) and coarse mesh (right) with every vertex coloured by
// its type (link green, I light blue, X purple, coarse-only red) and crease points pink.
#include <string>

#include "geometry/dog_model.h"
#include "ui/vis/offscreen.h"

namespace sdog::vis {

/// Renders the picture offscreen and writes it as PNG to `path`. Without a coarse mesh only the
/// fine mesh is drawn (vertices in the patch colour's place are grey).
void render_vertex_types(const DogModel& model, const std::string& path, const ImageSize& size,
                         bool transparent = false);

}  // namespace sdog::vis
