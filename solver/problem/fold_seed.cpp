#include "solver/problem/fold_seed.h"

#include <algorithm>
#include <limits>

namespace sdog {
namespace {

double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

}  // namespace

std::vector<bool> inside_own_patch(const DogMesh& mesh) {
  const int n = mesh.vertex_count();
  // Edges a crease crosses (strictly inside), per patch.
  std::vector<std::vector<int>> crossed(n);
  for (const auto& point : mesh.stitching.points)
    for (const EdgePoint& e : point.copies)
      if (e.v1 != e.v2) {
        crossed[e.v1].push_back(e.v2);
        crossed[e.v2].push_back(e.v1);
      }
  auto is_crossed = [&](int a, int b) {
    return std::find(crossed[a].begin(), crossed[a].end(), b) != crossed[a].end();
  };
  std::vector<std::vector<int>> neighbours(n);
  for (int q = 0; q < mesh.quad_count(); ++q)
    for (int k = 0; k < 4; ++k) {
      const int a = mesh.F(q, k), b = mesh.F(q, (k + 1) % 4);
      if (is_crossed(a, b)) continue;
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  // Distance of each vertex to the creases; per patch, flood from its farthest vertex without
  // crossing a crease: what is reached is the patch's own region.
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  for (int v = 0; v < n; ++v) {
    const Eigen::Vector2d p = mesh.V.row(v).head<2>().transpose();
    for (const auto& curve : mesh.stitching.curves) {
      const int m = static_cast<int>(curve.points.size());
      for (int k = 0; k + 1 < m + (curve.closed ? 1 : 0); ++k)
        dist[v] = std::min(dist[v],
                           segment_distance(p, mesh.stitching.points[curve.points[k]].flat,
                                            mesh.stitching.points[curve.points[(k + 1) % m]].flat));
    }
  }
  std::vector<bool> inside(n, false);
  for (int p = 0; p < mesh.patch_count(); ++p) {
    const int begin = mesh.patch_begin[p], end = mesh.patch_begin[p + 1];
    if (begin == end) continue;
    int seed = begin;
    for (int v = begin; v < end; ++v)
      if (dist[v] > dist[seed]) seed = v;
    std::vector<int> stack{seed};
    inside[seed] = true;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int u : neighbours[v])
        if (!inside[u]) {
          inside[u] = true;
          stack.push_back(u);
        }
    }
  }
  return inside;
}

Dofs fold_seed(const DogMesh& mesh, const std::vector<double>& curve_sign, double size) {
  Dofs x = to_dofs(mesh.V);
  if (std::none_of(curve_sign.begin(), curve_sign.end(), [](double s) { return s != 0; })) return x;
  const std::vector<bool> inside = inside_own_patch(mesh);
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const Eigen::Vector2d p = mesh.V.row(v).head<2>().transpose();
    double best = std::numeric_limits<double>::infinity();
    int nearest = -1;
    for (size_t c = 0; c < mesh.stitching.curves.size(); ++c) {
      const auto& curve = mesh.stitching.curves[c];
      const int m = static_cast<int>(curve.points.size());
      for (int k = 0; k + 1 < m + (curve.closed ? 1 : 0); ++k) {
        const double d = segment_distance(p, mesh.stitching.points[curve.points[k]].flat,
                                          mesh.stitching.points[curve.points[(k + 1) % m]].flat);
        if (d < best) best = d, nearest = static_cast<int>(c);
      }
    }
    if (nearest < 0 || nearest >= static_cast<int>(curve_sign.size())) continue;
    x[3 * v + 2] = curve_sign[nearest] * size * (inside[v] ? best : -best);
  }
  return x;
}

}  // namespace sdog
