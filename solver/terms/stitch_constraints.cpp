#include "solver/terms/stitch_constraints.h"

#include "solver/terms/crease_geometry.h"

namespace sdog {

StitchConstraints::StitchConstraints(const DogMesh& mesh) {
  for (const auto& pair : mesh.stitching.pairs) {
    const auto& point = mesh.stitching.points[pair.point];
    sides_.push_back({Side{point.copies[pair.a], point.patches[pair.a], 1.0},
                      Side{point.copies[pair.b], point.patches[pair.b], -1.0}});
  }
}

Eigen::Vector3d StitchConstraints::contribution(int pair, int s, const Dofs& x) const {
  const Side& side = sides_[pair][s];
  return side.sign * edge_point_position(side.copy, x);
}

Eigen::Vector3d StitchConstraints::residual(int pair, const Dofs& x) const {
  return contribution(pair, 0, x) + contribution(pair, 1, x);
}

Eigen::VectorXd StitchConstraints::residuals(const Dofs& x) const {
  Eigen::VectorXd r(3 * pair_count());
  for (int k = 0; k < pair_count(); ++k) r.segment<3>(3 * k) = residual(k, x);
  return r;
}

}  // namespace sdog
