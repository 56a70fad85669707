#pragma once
// Fine crease points from the coarse crease curve (coarse step 2 of the coarse mode): every fine
// crease point is a fixed linear combination of up to four coarse crease points, the cubic
// Lagrange interpolation of the coarse curve in its flat arc length. Exact at coarse points, and
// on a circular arc of the grid spacing h its error is O(h^4 kappa^3) instead of the chord's
// sagitta h^2 kappa / 8 (which alone is 0.03-0.06 grid units on the thesis patterns: more than the
// stitching tolerance).
#include <array>
#include <vector>

#include "geometry/mesh/dog_model.h"

namespace sdog {

struct CurveStencil {
  std::array<int, 4> points{};      ///< coarse crease point indices (mesh.stitching.points)
  std::array<double, 4> weights{};  ///< sum to one
  int count = 0;
};

/// stencils[c][k]: fine crease point k of curve c (the order of model.map.curves). Throws
/// std::logic_error for a point that the map cannot interpolate (segment -1).
std::vector<std::vector<CurveStencil>> coarse_curve_stencils(const DogModel& model);

/// Position of crease point `point` of `mesh` at positions X: the mean of its copies.
Eigen::Vector3d crease_point_mean(const DogMesh& mesh, const Eigen::MatrixX3d& X, int point);

/// The stencil's point at the coarse positions X.
Eigen::Vector3d interpolate(const DogMesh& coarse, const Eigen::MatrixX3d& X,
                            const CurveStencil& s);

}  // namespace sdog
