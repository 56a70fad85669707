#include "solver/terms/fold_angles.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace sdog {

FoldAngles::FoldAngles(const DogMesh& mesh)
    : mesh_(mesh), sites_(fold_sites(mesh)), site_of_(mesh.stitching.points.size(), -1) {
  const Dofs rest = to_dofs(mesh.V);
  for (size_t k = 0; k < sites_.size(); ++k) {
    site_of_[sites_[k].point] = static_cast<int>(k);
    own_v1_.push_back({own_end_is_v1(mesh, sites_[k], 0), own_end_is_v1(mesh, sites_[k], 1)});
    const Frame f = frame(k, rest);
    orientation_.push_back({f.normal[0].z() < 0 ? -1.0 : 1.0, f.normal[1].z() < 0 ? -1.0 : 1.0});
  }
}

FoldAngles::Frame FoldAngles::frame(size_t k, const Dofs& x) const {
  const FoldSite& site = sites_[k];
  const auto& points = mesh_.stitching.points;
  const auto& cp = points[site.point];
  const Eigen::Vector3d T = fold_site_tangent(mesh_, site, x);
  Frame f;
  for (int c = 0; c < 2; ++c) {
    const EdgePoint& e = cp.copies[c];
    // The whole edge, from its end beyond the crease to its end on the patch's own side: a crease
    // point near one end leaves too short a piece on that side to give a direction.
    const bool v1_own = own_v1_[k][c];
    const Eigen::Vector3d d = v1_own ? Eigen::Vector3d(vertex_of(x, e.v1) - vertex_of(x, e.v2))
                                     : Eigen::Vector3d(vertex_of(x, e.v2) - vertex_of(x, e.v1));
    f.u[c] = (d - d.dot(T) * T).normalized();
    f.normal[c] = T.cross(f.u[c]);
  }
  return f;
}

double FoldAngles::at(size_t k, const Dofs& x) const {
  const Frame f = frame(k, x);
  const double unsigned_angle = M_PI - std::acos(std::clamp(f.u[0].dot(f.u[1]), -1.0, 1.0));
  const Eigen::Vector3d n = orientation_[k][0] * f.normal[0] + orientation_[k][1] * f.normal[1];
  return ((f.u[0] + f.u[1]).dot(n) < 0 ? -unsigned_angle : unsigned_angle) / (M_PI / 180);
}

}  // namespace sdog
