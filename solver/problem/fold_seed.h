#pragma once
// Which way creases fold. The dihedral-angle targets are even in the angle (a cosine), and a flat
// sheet is a symmetric point: the out-of-plane gradient is zero, and an exact solver folds the
// sheet "in plane" by shearing it instead. The reference nudges vertices by unseeded random
// amounts; here the start state is tilted deterministically towards the requested fold:
//   z(v) = s_c * size * delta(v),
// with c the crease curve nearest to v, s_c = +1 for a valley fold (the sheet rises on both sides,
// seen from +z) and -1 for a mountain fold, and delta(v) the distance from v to c, positive where v
// is inside its own patch's region and negative on the patch's extension beyond a crease (so
// every patch starts as a plane tilted up, or down, away from its creases).
#include <vector>

#include "geometry/mesh/dog_mesh.h"
#include "solver/terms/term.h"

namespace sdog {

/// Per vertex: true when it lies in its patch's own region, false on the patch's one-cell
/// extension beyond a crease.
std::vector<bool> inside_own_patch(const DogMesh& mesh);

/// The flat state plus the tilt above; curve_sign[c] in {-1, 0, +1} (0: no tilt from that curve).
Dofs fold_seed(const DogMesh& mesh, const std::vector<double>& curve_sign, double size = 1e-3);

}  // namespace sdog
