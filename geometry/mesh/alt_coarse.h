#pragma once
// The thesis's alternative coarse DOG ("Alternative coarse mesh construction"): the fine DOG of a
// nested grid with every second grid row and column removed. In each patch the coarse vertices are
// the fine link vertices (even grid positions), and a coarse quad joins four of them wherever the
// patch has all four fine quads between them. Every coarse vertex is a link; there are no
// coarse-only vertices, so the coarse mesh no longer reaches across a crease, and it need not cover
// every fine vertex of its patch.
//
// Crease points: a fine crease point is kept as a coarse one when each of its copies lies on a
// coarse vertex or on a coarse edge of its patch (a fine edge that is half of a coarse quad's
// edge). The other fine crease points are interpolated between the kept ones along their crease
// (arc-length fractions, as in the standard map), except those before a crease's first or after
// its last kept point, which nothing interpolates (FineCoarseMap::CurvePoint with segment -1).
#include "geometry/mesh/dog_mesh.h"
#include "geometry/mesh/fine_coarse_map.h"

namespace sdog {

/// The alternative coarse DOG of a fine DOG built on a nested grid (coarse line k = fine line 2k):
/// same patches (a patch may get no coarse quad), same units, link vertices at the fine ones'
/// positions, the kept crease points stitched as in the fine mesh.
DogMesh build_alt_coarse_mesh(const DogMesh& fine);

/// The map between a fine DOG and its alternative coarse DOG: fine vertices typed by the parity of
/// their grid position, each with its coarse vertex, edge or quad where the coarse mesh has it
/// (else -1: FineCoarseMap::uncovered_count), every coarse vertex a link.
FineCoarseMap build_alt_fine_coarse_map(const DogMesh& fine, const DogMesh& coarse);

}  // namespace sdog
