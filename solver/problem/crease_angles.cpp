#include "solver/problem/crease_angles.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "base/text_format.h"

namespace sdog {
namespace {

constexpr double kDegree = M_PI / 180;
// Vertices within this distance (mesh units: grid cells) of a crease point decide its sides.
constexpr double kNearby = 4;

Eigen::Vector3d point_of(const DogMesh& mesh, int point, const Dofs& x) {
  const EdgePoint& e = mesh.stitching.points[point].copies.front();
  return e.t * vertex_of(x, e.v1) + (1 - e.t) * vertex_of(x, e.v2);
}

// An id as a CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

FoldAngles::FoldAngles(const DogMesh& mesh) : mesh_(mesh), sites_(fold_sites(mesh)) {
  const Dofs rest = to_dofs(mesh.V);
  for (const FoldSite& site : sites_) own_v1_.push_back({own_end_is_v1(site, 0), own_end_is_v1(site, 1)});
  for (const FoldSite& site : sites_) {
    const Frame f = frame(site, rest);
    orientation_.push_back({f.normal[0].z() < 0 ? -1.0 : 1.0, f.normal[1].z() < 0 ? -1.0 : 1.0});
  }
}

FoldAngles::Frame FoldAngles::frame(const FoldSite& site, const Dofs& x) const {
  const auto& cp = mesh_.stitching.points[site.point];
  const Eigen::Vector3d T = (point_of(mesh_, site.next, x) - point_of(mesh_, site.prev, x)).normalized();
  Frame f;
  for (int k = 0; k < 2; ++k) {
    const EdgePoint& e = cp.copies[k];
    // The whole edge, from its end beyond the crease to its end on the patch's own side: a crease
    // point near one end leaves too short a piece on that side to give a direction.
    const bool v1_own = own_v1_[&site - sites_.data()][k];
    const Eigen::Vector3d d = v1_own ? Eigen::Vector3d(vertex_of(x, e.v1) - vertex_of(x, e.v2))
                                     : Eigen::Vector3d(vertex_of(x, e.v2) - vertex_of(x, e.v1));
    f.u[k] = (d - d.dot(T) * T).normalized();
    f.normal[k] = T.cross(f.u[k]);
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
  const Frame f = frame(sites_[k], x);
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
    out << site.point << ',' << site.curve << ',' << csv_field(curve.id) << ',' << fold_name(curve.fold) << ','
        << format_number(flat.x()) << ',' << format_number(flat.y()) << ',';
    if (const auto it = target.find(site.point); it != target.end()) out << format_number(it->second);
    out << ',' << format_number(angles.at(k, x)) << '\n';
  }
  return out.str();
}

}  // namespace sdog
