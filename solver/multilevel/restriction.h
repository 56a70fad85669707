#pragma once
// Fine to coarse: the coarse state that goes with a (deformed) fine state, used when a coarse mode
// starts from a given state or takes over a run from another mode.
//
// A coarse vertex with a fine twin (link vertex) takes the twin's position. A coarse-only vertex
// (past a crease, where its patch's fine grid stops) has no fine counterpart: it is extrapolated
// with the quadratic map flat -> space, x(X, Y) = A [1, X, Y, X^2, XY, Y^2]^T, that best fits
// (least squares) the 12 fine vertices of the same patch nearest to it in the flat sheet. Those
// include the fine vertices past the crease, so the extrapolation continues the patch's own surface
// across the fold, and its curvature, as the fine mesh does (an affine fit to link vertices alone
// put coarse fold sites on the wrong side). Affine motions of the flat sheet are restricted
// exactly. The result is close to a DOG, not exactly one (CoarseLevel restores the constraints).
#include "geometry/mesh/dog_model.h"
#include "solver/terms/term.h"

namespace sdog {

/// Per fine crease point: the coarse crease point at the same flat position
/// (FineCoarseMap::curves), or -1. The model must have its coarse mesh.
std::vector<int> coarse_crease_twins(const DogModel& model);

/// Coarse positions for fine positions `fine_x`. The model must have its coarse mesh.
Dofs restrict_to_coarse(const DogModel& model, const Dofs& fine_x);

}  // namespace sdog
