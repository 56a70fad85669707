#include "solver/terms/crease_geometry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace sdog {

Eigen::Vector3d edge_point_position(const EdgePoint& e, const Dofs& x) {
  return e.t * vertex_of(x, e.v1) + (1 - e.t) * vertex_of(x, e.v2);
}

Eigen::Vector3d crease_point_position(const CreaseStitching::Point& point, const Dofs& x) {
  return edge_point_position(point.copies.front(), x);
}

Eigen::Vector3d circle_tangent(const Eigen::Vector3d& b, const Eigen::Vector3d& p,
                               const Eigen::Vector3d& f) {
  const Eigen::Vector3d t1 = p - b, t2 = f - p;
  return (t1 * t2.norm() + t2 * t1.norm()).normalized();
}

std::vector<FoldSite> fold_sites(const DogMesh& mesh) {
  // Neighbours along the crease closer than this (mesh units) give no direction: a crease through
  // (almost) a grid vertex crosses its two grid lines at (almost) the same point.
  constexpr double kMinChord = 0.05;
  const CreaseStitching& st = mesh.stitching;
  std::vector<FoldSite> sites;
  for (int c = 0; c < static_cast<int>(st.curves.size()); ++c) {
    const auto& curve = st.curves[c];
    if (curve.kind == CurveKind::kSlit) continue;  // its sides are free: nothing folds there
    const int n = static_cast<int>(curve.points.size());
    // The crease point `steps` along the curve from index k, or -1 past an open curve's end.
    auto along = [&](int k, int steps) {
      const int j = k + steps;
      if (!curve.closed && (j < 0 || j >= n)) return -1;
      return curve.points[(j % n + n) % n];
    };
    for (int k = 0; k < n; ++k) {
      const int point = curve.points[k];
      const auto& cp = st.points[point];
      const int prev = along(k, -1), next = along(k, 1);
      if (prev < 0 || next < 0 || cp.copies.size() != 2 || cp.copies[0].v1 == cp.copies[0].v2)
        continue;
      const Eigen::Vector2d p = cp.flat, b = st.points[prev].flat, f = st.points[next].flat;
      const double cross = (p - b).x() * (f - p).y() - (p - b).y() * (f - p).x();
      const double scale = (p - b).norm() * (f - p).norm();
      const bool flat = curve.fold == Fold::kFlat || std::abs(cross) <= 1e-9 * scale;
      // The nearest points at least kMinChord away, each way (the neighbours when there are none).
      auto chord_neighbour = [&](int dir, int fallback) {
        for (int steps = dir; std::abs(steps) < n; steps += dir) {
          const int q = along(k, steps);
          if (q < 0) break;
          if ((st.points[q].flat - p).norm() >= kMinChord) return q;
        }
        return fallback;
      };
      int chord_prev = chord_neighbour(-1, prev), chord_next = chord_neighbour(1, next);
      if (chord_prev == chord_next) chord_prev = prev, chord_next = next;
      sites.push_back({c, k, point, prev, next, chord_prev, chord_next, flat});
    }
  }
  return sites;
}

Eigen::Vector3d fold_site_tangent(const DogMesh& mesh, const FoldSite& site, const Dofs& x) {
  const auto& points = mesh.stitching.points;
  return circle_tangent(crease_point_position(points[site.chord_prev], x),
                        crease_point_position(points[site.point], x),
                        crease_point_position(points[site.chord_next], x));
}

namespace {

// The flat position of cell coordinates uv of quad q (F(q, 0) at (0, 0), F(q, 1) at (1, 0), F(q, 3)
// at (0, 1); cells are axis-aligned rectangles).
Eigen::Vector2d flat_point(const DogMesh& mesh, int q, const Eigen::Vector2d& uv) {
  const Eigen::Vector2d o = mesh.V.row(mesh.F(q, 0)).head<2>().transpose();
  const Eigen::Vector2d du = mesh.V.row(mesh.F(q, 1)).head<2>().transpose() - o;
  const Eigen::Vector2d dv = mesh.V.row(mesh.F(q, 3)).head<2>().transpose() - o;
  return o + uv.x() * du + uv.y() * dv;
}

}  // namespace

bool own_end_is_v1(const DogMesh& mesh, const FoldSite& site, int copy) {
  // The patch's piece of a cell on the edge that ends at the crease point holds the stretch of the
  // edge from the point to the own end: v1 is the own end when that stretch runs towards v1. (The
  // side of the piece's centroid cannot tell: a sliver between a curved crease and the edge has
  // its centroid almost on the crease's chord.)
  const auto& points = mesh.stitching.points;
  const auto& cp = points[site.point];
  const EdgePoint& e = cp.copies[copy];
  const int patch = cp.patches[copy];
  const Eigen::Vector2d p = cp.flat;
  const Eigen::Vector2d v1 = mesh.V.row(e.v1).head<2>().transpose();
  const Eigen::Vector2d along = (v1 - mesh.V.row(e.v2).head<2>().transpose()).normalized();
  const double tolerance = 1e-9 * (1 + p.norm());
  for (int q = mesh.quad_patch_begin[patch]; q < mesh.quad_patch_begin[patch + 1]; ++q) {
    int corners = 0;
    for (int k = 0; k < 4; ++k) corners += mesh.F(q, k) == e.v1 || mesh.F(q, k) == e.v2;
    if (corners != 2) continue;
    auto piece =
        std::lower_bound(mesh.quad_pieces.begin(), mesh.quad_pieces.end(), q,
                         [](const DogMesh::QuadPiece& a, int quad) { return a.quad < quad; });
    for (; piece != mesh.quad_pieces.end() && piece->quad == q; ++piece) {
      bool at_point = false;
      double towards_v1 = 0;
      for (const auto& uv : piece->uv) {
        const Eigen::Vector2d d = flat_point(mesh, q, uv) - p;
        if (d.norm() <= tolerance) {
          at_point = true;
        } else if (std::abs(along.x() * d.y() - along.y() * d.x()) <= tolerance) {
          towards_v1 = d.dot(along);  // a corner on the edge's line
        }
      }
      if (at_point && towards_v1 != 0) return towards_v1 > 0;
    }
  }
  // No piece ends at the point on the edge (not expected): the side of the crease's chord where
  // most of the patch's vertices near the crease point lie (a patch reaches a cell or two beyond
  // its creases).
  const Eigen::Vector2d t = points[site.chord_next].flat - points[site.chord_prev].flat;
  const Eigen::Vector2d n(-t.y(), t.x());
  const double v1_side = (v1 - p).dot(n);
  constexpr double kNearby = 4;
  double side = 0;
  for (int v = mesh.patch_begin[patch]; v < mesh.patch_begin[patch + 1]; ++v) {
    const Eigen::Vector2d d = mesh.V.row(v).head<2>().transpose() - p;
    if (d.squaredNorm() <= kNearby * kNearby) side += d.dot(n) > 0 ? 1 : -1;
  }
  return (v1_side > 0) == (side > 0);
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
    const double angle =
        std::acos(std::clamp((b - p).normalized().dot((p - f).normalized()), -1.0, 1.0));
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
