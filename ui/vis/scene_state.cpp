#include "ui/vis/scene_state.h"

#include <algorithm>
#include <cmath>

namespace sdog::vis {

ConstraintView constraint_view(const Scenario& scenario, double t) {
  ConstraintView view;
  for (const auto& p : scenario.positions)
    view.handles.push_back({p.vertex, p.start + t * (p.end - p.start)});
  for (const auto& a : scenario.angles)
    view.angle_sites.push_back({a.point, a.start_degrees + t * (a.end_degrees - a.start_degrees)});
  return view;
}

SceneState scene_state(const DogProblem& problem, const Dofs& x, const Dofs* coarse_x,
                       const Scenario* scenario, double t) {
  SceneState s;
  s.fine = to_positions(x);
  if (coarse_x) s.coarse = to_positions(*coarse_x);
  s.fields = fields(problem, x);
  if (scenario) s.constraints = constraint_view(*scenario, t);
  return s;
}

SceneState rest_scene_state(const DogModel& model, const Scenario* scenario) {
  const DogProblem problem(model.fine, model.fine_topology);
  return scene_state(problem, problem.rest(), nullptr, scenario, 1);
}

std::vector<double> log10_residuals(const std::vector<double>& residuals) {
  std::vector<double> out(residuals.size());
  std::transform(residuals.begin(), residuals.end(), out.begin(),
                 [](double r) { return std::log10(std::max(r, kResidualFloor)); });
  return out;
}

}  // namespace sdog::vis
