#include "geometry/surface/trimmed_surface.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>

#include <Eigen/Geometry>

namespace sdog {
namespace {

// A surface vertex as the mesh vertices it combines, with their weights (non-zero, by vertex).
using Combination = std::vector<std::pair<int, double>>;

// The bilinear combination of quad q's corners at cell coordinates (u, v).
Combination bilinear(const DogMesh& mesh, int q, const Eigen::Vector2d& uv) {
  const double u = uv.x(), v = uv.y();
  const std::array<double, 4> w{(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
  Combination c;
  for (int k = 0; k < 4; ++k)
    if (w[k] != 0) c.emplace_back(mesh.F(q, k), w[k]);
  std::sort(c.begin(), c.end());
  return c;
}

// Twice the signed area of triangle (a, b, c) in cell coordinates.
double doubled_area(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// Triangles of a convex counter-clockwise polygon whose vertices may include points on its sides
// (every vertex stays a triangle corner, so neighbouring pieces share their edges' points): ears
// with positive area are cut off one by one.
std::vector<std::array<int, 3>> triangulate_convex(const std::vector<Eigen::Vector2d>& poly) {
  std::vector<int> left(poly.size());
  for (size_t k = 0; k < poly.size(); ++k) left[k] = static_cast<int>(k);
  std::vector<std::array<int, 3>> triangles;
  constexpr double kFlat = 1e-12;
  while (left.size() >= 3) {
    const size_t n = left.size();
    size_t ear = n;
    for (size_t k = 0; k < n && ear == n; ++k)
      if (doubled_area(poly[left[(k + n - 1) % n]], poly[left[k]], poly[left[(k + 1) % n]]) > kFlat)
        ear = k;
    if (ear == n) break;  // what is left has no area
    triangles.push_back({left[(ear + n - 1) % n], left[ear], left[(ear + 1) % n]});
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(ear));
  }
  return triangles;
}

class SurfaceBuilder {
 public:
  explicit SurfaceBuilder(const DogMesh& mesh) : mesh_(mesh) {}

  void add_polygon(int q, const std::vector<Eigen::Vector2d>& uv) {
    std::vector<int> ids;
    for (const auto& p : uv) ids.push_back(vertex(q, p));
    for (const auto& t : triangulate_convex(uv)) {
      triangles_.push_back({ids[t[0]], ids[t[1]], ids[t[2]]});
      triangle_quad_.push_back(q);
    }
  }

  TrimmedSurface finish() && {
    TrimmedSurface s;
    const auto n = static_cast<Eigen::Index>(combinations_.size());
    s.source = Eigen::MatrixX4i::Zero(n, 4);
    s.weight = Eigen::MatrixX4d::Zero(n, 4);
    for (Eigen::Index r = 0; r < n; ++r) {
      const Combination& c = combinations_[r];
      for (size_t k = 0; k < c.size(); ++k) {
        s.source(r, static_cast<Eigen::Index>(k)) = c[k].first;
        s.weight(r, static_cast<Eigen::Index>(k)) = c[k].second;
      }
      for (size_t k = c.size(); k < 4; ++k) s.source(r, static_cast<Eigen::Index>(k)) = c[0].first;
    }
    s.T.resize(static_cast<Eigen::Index>(triangles_.size()), 3);
    for (size_t t = 0; t < triangles_.size(); ++t)
      s.T.row(static_cast<Eigen::Index>(t)) << triangles_[t][0], triangles_[t][1], triangles_[t][2];
    s.triangle_quad = std::move(triangle_quad_);
    s.vertex_patch = std::move(vertex_patch_);
    return s;
  }

 private:
  int vertex(int q, const Eigen::Vector2d& uv) {
    Combination c = bilinear(mesh_, q, uv);
    const int patch = mesh_.vertex_patch[mesh_.F(q, 0)];
    // The combination names the patch's own vertices, so equal combinations are one vertex of
    // one patch.
    auto [it, added] = index_.emplace(c, static_cast<int>(combinations_.size()));
    if (added) {
      combinations_.push_back(std::move(c));
      vertex_patch_.push_back(patch);
    }
    return it->second;
  }

  const DogMesh& mesh_;
  std::map<Combination, int> index_;
  std::vector<Combination> combinations_;
  std::vector<int> vertex_patch_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<int> triangle_quad_;
};

}  // namespace

TrimmedSurface trimmed_surface(const DogMesh& mesh, const Eigen::MatrixX3d& X) {
  SurfaceBuilder builder(mesh);
  const std::vector<Eigen::Vector2d> whole{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  auto piece = mesh.quad_pieces.begin();
  for (int q = 0; q < mesh.quad_count(); ++q) {
    if (piece == mesh.quad_pieces.end() || piece->quad != q) {
      builder.add_polygon(q, whole);
      continue;
    }
    for (; piece != mesh.quad_pieces.end() && piece->quad == q; ++piece)
      builder.add_polygon(q, piece->uv);
  }
  TrimmedSurface surface = std::move(builder).finish();
  place_trimmed_surface(surface, X);
  return surface;
}

void place_trimmed_surface(TrimmedSurface& s, const Eigen::MatrixX3d& X) {
  const Eigen::Index n = s.source.rows();
  s.V = Eigen::MatrixX3d::Zero(n, 3);
  for (Eigen::Index r = 0; r < n; ++r)
    for (int k = 0; k < 4; ++k) s.V.row(r) += s.weight(r, k) * X.row(s.source(r, k));
  s.N = Eigen::MatrixX3d::Zero(n, 3);
  for (Eigen::Index t = 0; t < s.T.rows(); ++t) {
    const Eigen::Vector3d a = s.V.row(s.T(t, 0)), b = s.V.row(s.T(t, 1)), c = s.V.row(s.T(t, 2));
    const Eigen::RowVector3d area_normal =
        (b - a).cross(c - a).transpose();  // twice the area, as its length
    for (int k = 0; k < 3; ++k) s.N.row(s.T(t, k)) += area_normal;
  }
  for (Eigen::Index r = 0; r < n; ++r) {
    const double length = s.N.row(r).norm();
    if (length > 0) s.N.row(r) /= length;
  }
}

std::vector<double> trimmed_point_values(const TrimmedSurface& s, const std::vector<double>& values,
                                         bool integral) {
  const Eigen::Index n = s.source.rows();
  std::vector<double> out(static_cast<size_t>(n));
  for (Eigen::Index r = 0; r < n; ++r) {
    double value = 0;
    if (integral) {
      Eigen::Index k;
      s.weight.row(r).maxCoeff(&k);
      value = values[s.source(r, k)];
    } else {
      for (int k = 0; k < 4; ++k) value += s.weight(r, k) * values[s.source(r, k)];
    }
    out[static_cast<size_t>(r)] = value;
  }
  return out;
}

std::vector<double> trimmed_cell_values(const TrimmedSurface& s,
                                        const std::vector<double>& values) {
  std::vector<double> out;
  out.reserve(s.triangle_quad.size());
  for (int q : s.triangle_quad) out.push_back(values[q]);
  return out;
}

MeshArrays trimmed_arrays(const TrimmedSurface& s, const MeshArrays& mesh_arrays) {
  MeshArrays out;
  for (const auto& a : mesh_arrays.point)
    out.point.push_back({a.name, trimmed_point_values(s, a.values, a.integral), a.integral});
  for (const auto& a : mesh_arrays.cell)
    out.cell.push_back({a.name, trimmed_cell_values(s, a.values), a.integral});
  return out;
}

double surface_area(const TrimmedSurface& s) {
  double area = 0;
  for (Eigen::Index t = 0; t < s.T.rows(); ++t) {
    const Eigen::Vector3d a = s.V.row(s.T(t, 0)), b = s.V.row(s.T(t, 1)), c = s.V.row(s.T(t, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

}  // namespace sdog
