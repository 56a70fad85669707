#include "geometry/surface/folded_form.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

namespace sdog {
namespace {

// FOLD vertex of each surface vertex: a vertex closer than tol to an earlier one of another patch
// shares its FOLD vertex (found in a hash grid of cell size tol).
std::vector<int> welded_vertices(const Eigen::MatrixX3d& V, const std::vector<int>& patch,
                                 double tol) {
  std::map<std::array<long long, 3>, std::vector<int>> cells;
  std::vector<int> fold_vertex(V.rows(), -1);
  int count = 0;
  auto cell = [&](double x) { return static_cast<long long>(std::floor(x / tol)); };
  for (int v = 0; v < V.rows(); ++v) {
    const std::array<long long, 3> c = {cell(V(v, 0)), cell(V(v, 1)), cell(V(v, 2))};
    for (long long dx = -1; dx <= 1 && fold_vertex[v] < 0; ++dx)
      for (long long dy = -1; dy <= 1 && fold_vertex[v] < 0; ++dy)
        for (long long dz = -1; dz <= 1 && fold_vertex[v] < 0; ++dz) {
          const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells.end()) continue;
          for (int w : it->second)
            if (patch[w] != patch[v] && (V.row(v) - V.row(w)).norm() <= tol) {
              fold_vertex[v] = fold_vertex[w];
              break;
            }
        }
    if (fold_vertex[v] < 0) {
      fold_vertex[v] = count++;
      cells[c].push_back(v);
    }
  }
  return fold_vertex;
}

Eigen::Vector3d triangle_normal(const TrimmedSurface& s, int t) {
  const Eigen::Vector3d a = s.V.row(s.T(t, 0)), b = s.V.row(s.T(t, 1)), c = s.V.row(s.T(t, 2));
  return (b - a).cross(c - a).normalized();
}

// Signed angle between the normals of triangles t1 and t2 across edge (a, b), degrees: positive
// when t2's far corner lies on the side t1's normal points to (the faces turn towards their
// normals: a valley).
double fold_angle(const TrimmedSurface& s, int t1, int t2) {
  const Eigen::Vector3d n1 = triangle_normal(s, t1), n2 = triangle_normal(s, t2);
  const double angle = std::acos(std::clamp(n1.dot(n2), -1.0, 1.0)) * 180 / M_PI;
  Eigen::Vector3d c1 = Eigen::Vector3d::Zero(), c2 = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) c1 += s.V.row(s.T(t1, k)), c2 += s.V.row(s.T(t2, k));
  return (c2 - c1).dot(n1) >= 0 ? angle : -angle;
}

}  // namespace

std::string folded_form_fold(const TrimmedSurface& surface, double weld_tolerance,
                             const std::string& title) {
  const std::vector<int> fv = welded_vertices(surface.V, surface.vertex_patch, weld_tolerance);
  const int n = surface.vertex_count() == 0 ? 0 : *std::max_element(fv.begin(), fv.end()) + 1;
  std::vector<std::array<double, 3>> coords(n);
  for (int v = surface.vertex_count() - 1; v >= 0; --v)
    coords[fv[v]] = {surface.V(v, 0), surface.V(v, 1), surface.V(v, 2)};
  std::vector<std::array<int, 3>> faces;
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;  // in order of first use
  std::vector<std::pair<int, int>> edges;
  for (int t = 0; t < surface.triangle_count(); ++t) {
    const std::array<int, 3> face = {fv[surface.T(t, 0)], fv[surface.T(t, 1)], fv[surface.T(t, 2)]};
    // Two corners welded to one vertex of another patch: a sliver at a crease point, left out.
    if (face[0] == face[1] || face[1] == face[2] || face[2] == face[0]) continue;
    faces.push_back(face);
    for (int k = 0; k < 3; ++k) {
      const int a = face[k], b = face[(k + 1) % 3];
      auto& list = edge_faces[{std::min(a, b), std::max(a, b)}];
      if (list.empty()) edges.push_back({std::min(a, b), std::max(a, b)});
      list.push_back(t);
    }
  }
  nlohmann::json vertices_edges = nlohmann::json::array(), assignment = nlohmann::json::array(),
                 angles = nlohmann::json::array();
  for (const auto& e : edges) {
    const std::vector<int>& f = edge_faces[e];
    vertices_edges.push_back({e.first, e.second});
    if (f.size() != 2) {
      assignment.push_back("B");
      angles.push_back(0.0);
      continue;
    }
    const double angle = fold_angle(surface, f[0], f[1]);
    const bool crease =
        surface.vertex_patch[surface.T(f[0], 0)] != surface.vertex_patch[surface.T(f[1], 0)];
    assignment.push_back(!crease                           ? "J"
                         : std::abs(angle) <= kFlatDegrees ? "F"
                         : angle > 0                       ? "V"
                                                           : "M");
    angles.push_back(angle);
  }
  nlohmann::ordered_json j;
  j["file_spec"] = 1.2;
  j["file_creator"] = "Scalable DOGs";
  j["file_classes"] = {"singleModel"};
  j["frame_title"] = title;
  j["frame_classes"] = {"foldedForm"};
  j["frame_attributes"] = {"3D", "joins"};
  j["vertices_coords"] = coords;
  j["faces_vertices"] = faces;
  j["edges_vertices"] = vertices_edges;
  j["edges_assignment"] = assignment;
  j["edges_foldAngle"] = angles;
  return j.dump() + "\n";
}

}  // namespace sdog
