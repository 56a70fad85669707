#include "solver/problem/crease_angles.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "base/csv.h"
#include "base/text_format.h"

namespace sdog {
namespace {

constexpr double kDegree = M_PI / 180;
// Vertices within this distance (mesh units: grid cells) of a crease point decide its sides.
constexpr double kNearby = 4;

}  // namespace

FoldAngles::FoldAngles(const DogMesh& mesh) : mesh_(mesh), sites_(fold_sites(mesh)) {
  const Dofs rest = to_dofs(mesh.V);
  for (size_t k = 0; k < sites_.size(); ++k) {
    own_v1_.push_back({own_end_is_v1(sites_[k], 0), own_end_is_v1(sites_[k], 1)});
    const Frame f = frame(k, rest);
    orientation_.push_back({f.normal[0].z() < 0 ? -1.0 : 1.0, f.normal[1].z() < 0 ? -1.0 : 1.0});
  }
}

FoldAngles::Frame FoldAngles::frame(size_t k, const Dofs& x) const {
  const FoldSite& site = sites_[k];
  const auto& points = mesh_.stitching.points;
  const auto& cp = points[site.point];
  const Eigen::Vector3d T =
      (crease_point_position(points[site.next], x) - crease_point_position(points[site.prev], x)).normalized();
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

bool FoldAngles::own_end_is_v1(const FoldSite& site, int copy) const {
  // A patch reaches a cell or two beyond its creases: its own side of the crease is the one where
  // most of its vertices near the crease point lie (at rest, across the crease's normal n).
  const auto& cp = mesh_.stitching.points[site.point];
  const EdgePoint& e = cp.copies[copy];
  const int patch = cp.patches[copy];
  const Eigen::Vector2d p = cp.flat;
  const Eigen::Vector2d t = mesh_.stitching.points[site.next].flat - mesh_.stitching.points[site.prev].flat;
  const Eigen::Vector2d n(-t.y(), t.x());
  double side = 0;
  for (int v = mesh_.patch_begin[patch]; v < mesh_.patch_begin[patch + 1]; ++v) {
    const Eigen::Vector2d d = mesh_.V.row(v).head<2>().transpose() - p;
    if (d.squaredNorm() <= kNearby * kNearby) side += d.dot(n) > 0 ? 1 : -1;
  }
  const double v1_side = (mesh_.V.row(e.v1).head<2>().transpose() - p).dot(n);
  return (v1_side > 0) == (side > 0);
}

double FoldAngles::at(size_t k, const Dofs& x) const {
  const Frame f = frame(k, x);
  const double unsigned_angle = M_PI - std::acos(std::clamp(f.u[0].dot(f.u[1]), -1.0, 1.0));
  const Eigen::Vector3d n = orientation_[k][0] * f.normal[0] + orientation_[k][1] * f.normal[1];
  return ((f.u[0] + f.u[1]).dot(n) < 0 ? -unsigned_angle : unsigned_angle) / kDegree;
}

std::string creases_csv(const DogMesh& mesh, const Scenario& scenario, const Dofs& x) {
  const FoldAngles angles(mesh);
  std::map<int, double> target;  // crease point -> the scenario's final angle there
  for (const auto& a : scenario.angles) target[a.point] = a.end_degrees;
  std::ostringstream out;
  out << "crease_point,crease,id,assignment,x,y,target_angle,angle\n";
  for (size_t k = 0; k < angles.sites().size(); ++k) {
    const FoldSite& site = angles.sites()[k];
    const auto& curve = mesh.stitching.curves[site.curve];
    const Eigen::Vector2d flat = mesh.stitching.points[site.point].flat;
    const auto it = target.find(site.point);
    out << csv_line({std::to_string(site.point), std::to_string(site.curve), curve.id, fold_name(curve.fold),
                     format_number(flat.x()), format_number(flat.y()),
                     it != target.end() ? format_number(it->second) : std::string(), format_number(angles.at(k, x))})
        << '\n';
  }
  return out.str();
}

}  // namespace sdog
