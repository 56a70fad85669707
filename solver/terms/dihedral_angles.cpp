#include "solver/terms/dihedral_angles.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace sdog {

DihedralSite dihedral_site(const DogMesh& mesh, const FoldSite& site) {
  const auto& points = mesh.stitching.points;
  const auto& cp = points[site.point];
  const EdgePoint& a = cp.copies[0];
  const EdgePoint& b = cp.copies[1];
  const EdgePoint& prev = points[site.chord_prev].copies.front();
  const EdgePoint& next = points[site.chord_next].copies.front();
  DihedralSite d;
  d.point = site.point;
  d.vertices = {a.v1, a.v2, b.v1, b.v2, prev.v1, prev.v2, next.v1, next.v2};
  d.t = {a.t, prev.t, next.t};
  const Dofs rest = to_dofs(mesh.V);
  const Eigen::Vector3d ea = vertex_of(rest, a.v1) - vertex_of(rest, a.v2);
  const Eigen::Vector3d T = fold_site_tangent(mesh, site, rest);
  // alpha and pi - alpha give the same rows.
  d.alpha = std::acos(std::clamp(std::abs(T.dot(ea.normalized())), 0.0, 1.0));
  // Folding a valley by a small angle lifts copy A's own side of the edge (d_A) and copy B's own
  // side, so e_A x e_B = -2 tan(theta / 2) (e . d_A) e x z, and (e_A x e_B) . T has the sign of
  // -d_A . (z x T).
  const Eigen::Vector3d d_a = own_end_is_v1(mesh, site, 0) ? ea : Eigen::Vector3d(-ea);
  d.orientation = d_a.dot(Eigen::Vector3d::UnitZ().cross(T)) > 0 ? -1.0 : 1.0;
  return d;
}

std::vector<DihedralSite> seam_vertex_sites(const DogMesh& mesh) {
  const CreaseStitching& st = mesh.stitching;
  std::vector<DihedralSite> out;
  for (const auto& curve : st.curves) {
    if (curve.kind != CurveKind::kSeam) continue;
    for (size_t k = 1; k + 1 < curve.points.size(); ++k) {
      const auto& cp = st.points[curve.points[k]];
      if (cp.copies.size() != 2 || cp.copies[0].v1 != cp.copies[0].v2 ||
          cp.copies[1].v1 != cp.copies[1].v2)
        continue;
      const int va = cp.copies[0].v1, vb = cp.copies[1].v1;
      const Eigen::Vector2d T =
          st.points[curve.points[k + 1]].flat - st.points[curve.points[k - 1]].flat;
      // Across the seam: along x for a seam closer to vertical, else along y.
      const Eigen::Vector2i step =
          std::abs(T.x()) < std::abs(T.y()) ? Eigen::Vector2i(1, 0) : Eigen::Vector2i(0, 1);
      auto neighbour = [&](int v, int side) {
        const Eigen::Vector2i g = mesh.grid[v] + side * step;
        return mesh.vertex_at(mesh.vertex_patch[v], g.x(), g.y());
      };
      int side_a = 0;
      for (const int side : {-1, 1})
        if (neighbour(va, side) >= 0 && neighbour(va, -side) < 0 && neighbour(vb, -side) >= 0 &&
            neighbour(vb, side) < 0)
          side_a = side;
      if (side_a == 0) continue;
      const EdgePoint& prev = st.points[curve.points[k - 1]].copies.front();
      const EdgePoint& next = st.points[curve.points[k + 1]].copies.front();
      DihedralSite d;
      d.point = curve.points[k];
      d.vertices = {neighbour(va, side_a),
                    va,
                    vb,
                    neighbour(vb, -side_a),
                    prev.v1,
                    prev.v2,
                    next.v1,
                    next.v2};
      d.t = {0, prev.t, next.t};
      d.alpha = M_PI / 2;
      out.push_back(d);
    }
  }
  return out;
}

int DihedralAngleTerm::add(const DihedralSite& site, double theta) {
  std::vector<int> unique;
  Block k;
  for (int r = 0; r < 8; ++r) {
    auto it = std::find(unique.begin(), unique.end(), site.vertices[r]);
    if (it == unique.end()) it = unique.insert(unique.end(), site.vertices[r]);
    k.slot[r] = static_cast<int>(it - unique.begin());
  }
  k.t = site.t;
  k.orientation = site.orientation;
  add_block(unique.data(), static_cast<int>(unique.size()), 2);
  blocks_.push_back(k);
  sites_.push_back(site);
  theta_.push_back(0);
  const int b = block_count() - 1;
  set_target(b, theta);
  return b;
}

void DihedralAngleTerm::set_target(int b, double theta) {
  const double c = std::cos(sites_[b].alpha), s = std::sin(sites_[b].alpha);
  theta_[b] = theta;
  blocks_[b].cos_target = c * c + s * s * std::cos(theta);
  blocks_[b].sin_target = s * s * std::sin(theta);
}

double DihedralAngleTerm::measure(int b, const Eigen::Vector3d* p) const {
  double r[2];
  evaluate(b, p, r, nullptr);
  const double c = std::cos(sites_[b].alpha);
  return std::atan2(r[1] + blocks_[b].sin_target, r[0] + blocks_[b].cos_target - c * c);
}

void DihedralAngleTerm::clear() {
  clear_blocks();
  blocks_.clear();
  sites_.clear();
  theta_.clear();
}

void DihedralAngleTerm::evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const {
  const Block& k = blocks_[b];
  const Eigen::Vector3d eA = p[k.slot[0]] - p[k.slot[1]], eB = p[k.slot[2]] - p[k.slot[3]];
  const Eigen::Vector3d P = k.t[0] * p[k.slot[0]] + (1 - k.t[0]) * p[k.slot[1]];
  const Eigen::Vector3d Pb = k.t[1] * p[k.slot[4]] + (1 - k.t[1]) * p[k.slot[5]];
  const Eigen::Vector3d Pf = k.t[2] * p[k.slot[6]] + (1 - k.t[2]) * p[k.slot[7]];
  const Eigen::Vector3d t1 = P - Pb, t2 = Pf - P;
  const double n1 = t1.norm(), n2 = t2.norm(), lA = eA.norm(), lB = eB.norm();
  const Eigen::Vector3d v = t1 * n2 + t2 * n1;
  const double nv = v.norm();
  const Eigen::Vector3d T = v / nv, a = eA / lA, bb = eB / lB, w = a.cross(bb);
  r[0] = a.dot(bb) - k.cos_target;
  r[1] = k.orientation * w.dot(T) - k.sin_target;
  if (!J) return;
  const int cols = 3 * block_size(b);
  std::fill(J, J + 2 * cols, 0.0);
  auto add = [&](int row, int role, double scale, const Eigen::Vector3d& g) {
    for (int c = 0; c < 3; ++c) J[row * cols + 3 * k.slot[role] + c] += scale * g[c];
  };
  // d(unit e) = (I - u u^T) de / |e|.
  auto through_unit = [](const Eigen::Vector3d& u, double length, const Eigen::Vector3d& g) {
    return Eigen::Vector3d((g - u.dot(g) * u) / length);
  };
  // Row 0: c = a . b.
  const Eigen::Vector3d cA = through_unit(a, lA, bb), cB = through_unit(bb, lB, a);
  add(0, 0, 1, cA);
  add(0, 1, -1, cA);
  add(0, 2, 1, cB);
  add(0, 3, -1, cB);
  // Row 1: s = sigma w . T with w = a x b and T = v / |v|:
  // d(w.T) = da . (b x T) + db . (T x a) + g . dv, g = (I - T T^T) w / |v|,
  // v = t1 |t2| + t2 |t1|: dv/dt1 = |t2| I + t2 t1^T / |t1|, dv/dt2 = |t1| I + t1 t2^T / |t2|.
  const double s = k.orientation;
  const Eigen::Vector3d gA = through_unit(a, lA, bb.cross(T)),
                        gB = through_unit(bb, lB, T.cross(a));
  const Eigen::Vector3d g = (w - w.dot(T) * T) / nv;
  const Eigen::Vector3d g1 = n2 * g + t1 * (t2.dot(g) / n1), g2 = n1 * g + t2 * (t1.dot(g) / n2);
  const Eigen::Vector3d gP = g1 - g2;  // t1 = P - Pb, t2 = Pf - P
  add(1, 0, s, gA);
  add(1, 1, -s, gA);
  add(1, 2, s, gB);
  add(1, 3, -s, gB);
  add(1, 0, s * k.t[0], gP);
  add(1, 1, s * (1 - k.t[0]), gP);
  add(1, 4, -s * k.t[1], g1);
  add(1, 5, -s * (1 - k.t[1]), g1);
  add(1, 6, s * k.t[2], g2);
  add(1, 7, s * (1 - k.t[2]), g2);
}

}  // namespace sdog
