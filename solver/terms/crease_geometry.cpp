#include "solver/terms/crease_geometry.h"

#include <Eigen/Geometry>
#include <cmath>

namespace sdog {

CreaseNeighbours crease_neighbours(const CreaseStitching::Curve& curve, int k) {
  const int n = static_cast<int>(curve.points.size());
  CreaseNeighbours out;
  if (curve.closed) {
    out.prev = curve.points[(k + n - 1) % n];
    out.next = curve.points[(k + 1) % n];
  } else {
    if (k > 0) out.prev = curve.points[k - 1];
    if (k + 1 < n) out.next = curve.points[k + 1];
  }
  return out;
}

Eigen::Vector3d edge_point_position(const EdgePoint& e, const Dofs& x) {
  return e.t * vertex_of(x, e.v1) + (1 - e.t) * vertex_of(x, e.v2);
}

Eigen::Vector3d crease_point_position(const CreaseStitching::Point& point, const Dofs& x) {
  return edge_point_position(point.copies.front(), x);
}

Eigen::Vector3d circle_tangent(const Eigen::Vector3d& b, const Eigen::Vector3d& p, const Eigen::Vector3d& f) {
  const Eigen::Vector3d t1 = p - b, t2 = f - p;
  return (t1 * t2.norm() + t2 * t1.norm()).normalized();
}

std::vector<FoldSite> fold_sites(const DogMesh& mesh) {
  const CreaseStitching& st = mesh.stitching;
  const Dofs rest = to_dofs(mesh.V);
  std::vector<FoldSite> sites;
  for (int c = 0; c < static_cast<int>(st.curves.size()); ++c) {
    const auto& curve = st.curves[c];
    for (int k = 0; k < static_cast<int>(curve.points.size()); ++k) {
      const int point = curve.points[k];
      const auto& cp = st.points[point];
      const CreaseNeighbours nb = crease_neighbours(curve, k);
      if (nb.prev < 0 || nb.next < 0 || cp.copies.size() != 2 || cp.copies[0].v1 == cp.copies[0].v2) continue;
      const Eigen::Vector3d p = crease_point_position(cp, rest);
      const Eigen::Vector3d b = crease_point_position(st.points[nb.prev], rest);
      const Eigen::Vector3d f = crease_point_position(st.points[nb.next], rest);
      const double scale = (p - b).norm() * (f - p).norm();
      const bool flat = curve.fold == Fold::kFlat || ((p - b).cross(f - p)).norm() <= 1e-9 * scale;
      sites.push_back({c, k, point, nb.prev, nb.next, flat});
    }
  }
  return sites;
}

FoldCheck check_folded(const DogMesh& mesh, const std::vector<FoldSite>& sites, const Dofs& x) {
  const CreaseStitching& st = mesh.stitching;
  FoldCheck check;
  for (const auto& s : sites) {
    const auto& cp = st.points[s.point];
    const EdgePoint& c1 = cp.copies[0];
    const EdgePoint& c2 = cp.copies[1];
    if (s.flat || c1.t < 0.05 || c1.t > 0.95) continue;
    const Eigen::Vector3d p = crease_point_position(cp, x);
    const Eigen::Vector3d b = crease_point_position(st.points[s.prev], x);
    const Eigen::Vector3d f = crease_point_position(st.points[s.next], x);
    const Eigen::Vector3d e1 = vertex_of(x, c1.v1) - vertex_of(x, c1.v2);
    const Eigen::Vector3d e2 = vertex_of(x, c2.v1) - vertex_of(x, c2.v2);
    // Skip where the crease runs almost along the edge or has no osculating plane.
    if (std::abs((p - b).normalized().dot(e1.normalized())) > 0.9995 ||
        std::abs((f - p).normalized().dot(e1.normalized())) > 0.9995)
      continue;
    const double angle = std::acos(std::clamp((b - p).normalized().dot((p - f).normalized()), -1.0, 1.0));
    if (std::sin(angle) / (f - b).norm() < 1e-5) continue;
    const Eigen::Vector3d B = (p - b).cross(f - p);
    ++check.checked;
    if (B.dot(e1) * B.dot(e2) > 0) {
      ++check.violations;
      check.folded = false;
    }
  }
  return check;
}

}  // namespace sdog
