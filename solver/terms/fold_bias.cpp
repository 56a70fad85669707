#include "solver/terms/fold_bias.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace sdog {

FoldBiasTerm::FoldBiasTerm(const DogMesh& mesh, const std::vector<FoldSite>& sites,
                           double sharpness)
    : sharpness_(sharpness) {
  const CreaseStitching& st = mesh.stitching;
  for (const auto& s : sites) {
    if (s.flat) continue;
    const auto& cp = st.points[s.point];
    const EdgePoint& pb = st.points[s.prev].copies.front();
    const EdgePoint& pf = st.points[s.next].copies.front();
    const int roles[8] = {cp.copies[0].v1, cp.copies[0].v2, cp.copies[1].v1, cp.copies[1].v2,
                          pb.v1,           pb.v2,           pf.v1,           pf.v2};
    std::vector<int> unique;
    Site site;
    for (int r = 0; r < 8; ++r) {
      auto it = std::find(unique.begin(), unique.end(), roles[r]);
      if (it == unique.end()) it = unique.insert(unique.end(), roles[r]);
      site.slot[r] = static_cast<int>(it - unique.begin());
    }
    site.t = {cp.copies[0].t, cp.copies[1].t, pb.t, pf.t};
    add_block(unique.data(), static_cast<int>(unique.size()), 1);
    sites_.push_back(site);
  }
}

void FoldBiasTerm::evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const {
  const Site& s = sites_[b];
  const Eigen::Vector3d P = s.t[0] * p[s.slot[0]] + (1 - s.t[0]) * p[s.slot[1]];
  const Eigen::Vector3d Pb = s.t[2] * p[s.slot[4]] + (1 - s.t[2]) * p[s.slot[5]];
  const Eigen::Vector3d Pf = s.t[3] * p[s.slot[6]] + (1 - s.t[3]) * p[s.slot[7]];
  const Eigen::Vector3d a = Pb - P, f = Pf - P, B = a.cross(f);
  const Eigen::Vector3d e1 = p[s.slot[0]] - p[s.slot[1]], e2 = p[s.slot[2]] - p[s.slot[3]];
  const double h1 = std::tanh(sharpness_ * B.dot(e1)), h2 = std::tanh(sharpness_ * B.dot(e2));
  r[0] = h1 + h2;
  if (!J) return;
  const int cols = 3 * block_size(b);
  std::fill(J, J + cols, 0.0);
  auto add = [&](int role, double scale, const Eigen::Vector3d& g) {
    for (int c = 0; c < 3; ++c) J[3 * s.slot[role] + c] += scale * g[c];
  };
  // d(B.e)/da = f x e, d(B.e)/df = e x a, d(B.e)/de = B; a = Pb - P, f = Pf - P.
  const double k1 = sharpness_ * (1 - h1 * h1), k2 = sharpness_ * (1 - h2 * h2);
  const Eigen::Vector3d ga = k1 * f.cross(e1) + k2 * f.cross(e2);
  const Eigen::Vector3d gf = k1 * e1.cross(a) + k2 * e2.cross(a);
  const Eigen::Vector3d gP = -(ga + gf);
  add(4, s.t[2], ga);
  add(5, 1 - s.t[2], ga);
  add(6, s.t[3], gf);
  add(7, 1 - s.t[3], gf);
  add(0, s.t[0], gP);
  add(1, 1 - s.t[0], gP);
  add(0, 1, k1 * B);
  add(1, -1, k1 * B);
  add(2, 1, k2 * B);
  add(3, -1, k2 * B);
}

}  // namespace sdog
