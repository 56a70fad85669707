#include "solver/problem/scenario.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "solver/problem/fold_seed.h"

namespace sdog {
namespace {

constexpr double kDegree = M_PI / 180;

// Vertices at a grid corner (several when a crease ends there); -1 if none.
int grid_corner_vertex(const DogMesh& mesh, int i, int j, bool last) {
  int found = -1;
  for (int v = 0; v < mesh.vertex_count(); ++v)
    if (mesh.grid[v] == Eigen::Vector2i(i, j)) {
      found = v;
      if (!last) break;
    }
  return found;
}

int nearest_vertex(const DogMesh& mesh, const Eigen::Vector2d& p) {
  int best = 0;
  for (int v = 1; v < mesh.vertex_count(); ++v)
    if ((mesh.V.row(v).head<2>().transpose() - p).squaredNorm() <
        (mesh.V.row(best).head<2>().transpose() - p).squaredNorm())
      best = v;
  return best;
}

}  // namespace

const FoldSite* find_fold_site(const std::vector<FoldSite>& sites, int point) {
  for (const auto& site : sites)
    if (site.point == point) return &site;
  return nullptr;
}

void Scenario::install(DogProblem& problem) const {
  if (!keeps_folds) problem.weights.fold_bias = 0;  // nothing may push the creases to stay folded
  problem.positions.clear();
  for (const auto& pc : positions) problem.positions.add({{pc.vertex, 1.0}}, pc.start);
  problem.angles.clear();
  for (const auto& ac : angles) {
    const FoldSite* site = find_fold_site(problem.sites, ac.point);
    if (!site)
      throw std::logic_error("crease point " + std::to_string(ac.point) + " is no fold site");
    problem.angles.add(dihedral_site(problem.mesh(), *site), 0);
  }
  // Seams keep the paper smooth in every scenario: angle target zero (apply() leaves them).
  std::vector<char> targeted(problem.mesh().stitching.points.size(), 0);
  for (const auto& ac : angles) targeted[ac.point] = 1;
  for (const auto& site : problem.sites)
    if (problem.mesh().stitching.curves[site.curve].kind == CurveKind::kSeam &&
        !targeted[site.point])
      problem.angles.add(dihedral_site(problem.mesh(), site), 0);
  for (const DihedralSite& site : seam_vertex_sites(problem.mesh()))
    if (!targeted[site.point]) problem.angles.add(site, 0);
  problem.update_free_sites();
  apply(problem, 0);
}

void Scenario::apply(DogProblem& problem, double t) const {
  for (size_t k = 0; k < positions.size(); ++k)
    problem.positions.set_target(static_cast<int>(k),
                                 positions[k].start + t * (positions[k].end - positions[k].start));
  for (size_t k = 0; k < angles.size(); ++k) {
    const auto& ac = angles[k];
    problem.angles.set_target(
        static_cast<int>(k),
        (ac.start_degrees + t * (ac.end_degrees - ac.start_degrees)) * kDegree);
  }
}

double Scenario::time_of(int iteration) const {
  return iterations <= 0 ? 1.0 : std::min(1.0, static_cast<double>(iteration) / iterations);
}

Dofs Scenario::start(const DogMesh& mesh) const {
  return initial.size() > 0 ? initial : fold_seed(mesh, curve_signs);
}

Scenario corners_scenario(const DogMesh& mesh, int iterations, int hold) {
  Scenario s;
  s.name = "corners";
  s.iterations = iterations;
  s.hold = hold;
  int a = grid_corner_vertex(mesh, 0, 0, false);
  int c = grid_corner_vertex(mesh, mesh.nx() - 1, mesh.ny() - 1, true);
  if (a < 0) a = nearest_vertex(mesh, {mesh.xs.front(), mesh.ys.front()});
  if (c < 0) c = nearest_vertex(mesh, {mesh.xs.back(), mesh.ys.back()});
  const Eigen::Vector3d pa = mesh.V.row(a).transpose(), pc = mesh.V.row(c).transpose();
  s.positions.push_back({a, pa, pa});
  s.positions.push_back(
      {c, pc, Eigen::Vector3d(0.6 * pc.x(), 0.5 * (pc.y() + pa.y()), 0.4 * (pc.y() + pa.y()))});
  return s;
}

Scenario fold_scenario(const DogMesh& mesh, double degrees, int iterations, int hold,
                       double percent) {
  Scenario s;
  s.name = "fold";
  s.iterations = iterations;
  s.hold = hold;
  s.curve_signs.resize(mesh.stitching.curves.size(), 0.0);
  for (size_t c = 0; c < mesh.stitching.curves.size(); ++c) {
    const double target = crease_fold_target(mesh, c, degrees);
    s.curve_signs[c] = target > 0 ? 1.0 : target < 0 ? -1.0 : 0.0;
  }
  const std::vector<FoldFade> fades = fold_fades(mesh);
  for (const auto& site : fold_sites(mesh))
    s.angles.push_back(
        {site.point, 0.0,
         percent / 100 * fades[site.curve].at(mesh.stitching.points[site.point].flat) *
             crease_fold_target(mesh, site.curve, degrees)});
  return s;
}

double FoldFade::at(const Eigen::Vector2d& p) const {
  double fade = 1;
  for (const Eigen::Vector2d& end : inner_ends)
    fade = std::min(fade, (p - end).norm() / (kFadeShare * length));
  return fade;
}

std::vector<FoldFade> fold_fades(const DogMesh& mesh) {
  const CreaseStitching& st = mesh.stitching;
  std::set<int> seam_starts;
  for (const auto& seam : st.curves)
    if (seam.kind == CurveKind::kSeam && !seam.points.empty())
      seam_starts.insert(seam.points.front());
  std::vector<FoldFade> fades(st.curves.size());
  for (size_t i = 0; i < st.curves.size(); ++i) {
    const auto& c = st.curves[i];
    if (c.closed || c.kind != CurveKind::kCrease || c.points.size() < 2) continue;
    for (size_t k = 1; k < c.points.size(); ++k)
      fades[i].length += (st.points[c.points[k]].flat - st.points[c.points[k - 1]].flat).norm();
    for (const int end : {c.points.front(), c.points.back()})
      if (seam_starts.count(end)) fades[i].inner_ends.push_back(st.points[end].flat);
  }
  return fades;
}

double crease_fold_target(const DogMesh& mesh, size_t curve, double degrees) {
  const auto& c = mesh.stitching.curves[curve];
  if (c.fold == Fold::kFlat) return 0;
  const double size = c.angle ? *c.angle : std::abs(degrees);
  const double sign = c.fold == Fold::kUnassigned ? (degrees < 0 ? -1.0 : 1.0) : fold_sign(c.fold);
  return sign * size;
}

}  // namespace sdog
