#include "solver/problem/crease_angles.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "base/csv.h"
#include "base/statistics.h"
#include "base/text_format.h"
#include "solver/problem/diagnostics.h"

namespace sdog {
namespace {

constexpr double kDegree = M_PI / 180;

}  // namespace

std::vector<CreaseFold> crease_folds(const DogProblem& problem, const Dofs& x) {
  const auto& curves = problem.mesh().stitching.curves;
  struct Collected {
    CreaseFold fold;
    std::vector<double> targets, angles, errors;
  };
  std::vector<Collected> by_curve(curves.size());
  for (int b = 0; b < problem.angles.block_count(); ++b) {
    const int k = problem.fold_angles.site_of(problem.angles.point(b));
    if (k < 0) continue;
    Collected& c = by_curve[problem.fold_angles.sites()[k].curve];
    const double target = problem.angles.target(b) / kDegree, angle = problem.fold_angles.at(k, x);
    ++c.fold.sites;
    c.targets.push_back(target);
    c.angles.push_back(angle);
    c.errors.push_back(std::abs(angle_difference(angle, target)));
    if (std::abs(angle) <= kBentDegrees || target == 0) continue;
    ++c.fold.bent;
    if (!bent_against(angle, target)) continue;
    ++c.fold.against;
    if (near_fold_tip(problem.mesh(), problem.angles.point(b))) ++c.fold.against_near_tip;
  }
  std::vector<CreaseFold> out;
  for (size_t curve = 0; curve < by_curve.size(); ++curve) {
    Collected& c = by_curve[curve];
    if (c.fold.sites == 0) continue;
    c.fold.curve = static_cast<int>(curve);
    c.fold.target = median(c.targets);
    c.fold.angle = median(c.angles);
    c.fold.median_error = median(c.errors);
    out.push_back(c.fold);
  }
  return out;
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
    out << csv_line({std::to_string(site.point), std::to_string(site.curve), curve.id,
                     enum_name(curve.fold), format_number(flat.x()), format_number(flat.y()),
                     it != target.end() ? format_number(it->second) : std::string(),
                     format_number(angles.at(k, x))});
  }
  return out.str();
}

}  // namespace sdog
