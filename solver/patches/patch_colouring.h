#pragma once
// Colours of the patch graph (patches are neighbours when a crease stitches them together), for
// patch rounds that step one colour at a time with the others frozen (Gauss-Seidel by colour): no
// two neighbours then move in the same half-round, so the two sides of a fold site never move
// against each other's old position at once.
#include <vector>

#include "geometry/mesh/dog_mesh.h"

namespace sdog {

/// Colour of every patch (0, 1, ...): greedy in patch order, neighbours differ; at most the
/// largest number of neighbours + 1 colours.
std::vector<int> colour_patches(const DogMesh& mesh);

}  // namespace sdog
