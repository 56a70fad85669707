#include "solver/coarse_level.h"

#include "geometry/errors.h"

namespace sdog {
namespace {

const DogModel& with_coarse(const DogModel& model, const std::string& mode_name) {
  if (!model.has_coarse)
    throw UsageError("mode " + mode_name + " needs the coarse mesh (odd resolutions, not --fine-only)");
  return model;
}

}  // namespace

CoarseLevel::CoarseLevel(const DogProblem& fine, const DogModel& model, const Scenario& scenario, double link_weight,
                         const StandardOptions& standard, const std::string& mode_name)
    : model_(model), link_weight_(link_weight), prolongation_(with_coarse(model, mode_name)) {
  if (!scenario.angles.empty())
    throw UsageError("mode " + mode_name + " does not support dihedral angle constraints yet (scenario '" +
                     scenario.name + "' has " + std::to_string(scenario.angles.size()) + "); use --mode standard");
  if (scenario.initial.size() > 0)
    throw UsageError("mode " + mode_name + " cannot start from a given state yet (scenario '" + scenario.name +
                     "'): there is no fine-to-coarse restriction of a deformed state; use another mode");
  const FineCoarseMap& map = model.map;
  Scenario coarse_scenario = scenario;
  coarse_scenario.positions.clear();
  for (const auto& p : scenario.positions) {
    if (map.fine_to_coarse[p.vertex] >= 0)
      coarse_scenario.positions.push_back({map.fine_to_coarse[p.vertex], p.start, p.end});
    else
      carried_.push_back(p);
  }
  coarse_scenario.curve_signs.resize(model.coarse.stitching.curves.size(), 0.0);  // curves correspond by index
  Weights weights = fine.weights;
  weights.link = link_weight;
  weights.edge_points = weights.positions;  // the carried position targets
  problem_ = std::make_unique<DogProblem>(model.coarse, model.coarse_topology, weights);
  // Blocks before the solver fixes its pattern.
  for (const auto& p : carried_) problem_->edge_points.add(prolongation_.row(p.vertex));
  for (int v = 0; v < model.fine.vertex_count(); ++v)
    if (map.fine_to_coarse[v] >= 0) {
      links_.push_back({v, map.fine_to_coarse[v]});
      problem_->link.add({{map.fine_to_coarse[v], 1.0}});
    }
  mode_ = std::make_unique<StandardMode>(*problem_, coarse_scenario, standard);
  x_ = coarse_scenario.start(model.coarse);
  set_time(0);
}

CoarseLevel::~CoarseLevel() = default;

void CoarseLevel::set_time(double t) {
  mode_->set_time(t);
  for (size_t k = 0; k < carried_.size(); ++k)
    problem_->edge_points.set_target(static_cast<int>(k), carried_[k].start + t * (carried_[k].end - carried_[k].start));
}

StepReport CoarseLevel::step(const Dofs& fine_x, bool last) {
  if (link_weight_ > 0)
    for (size_t i = 0; i < links_.size(); ++i)
      problem_->link.set_target(static_cast<int>(i), Eigen::Vector3d(vertex_of(fine_x, links_[i].first)));
  return mode_->iterate(x_, last);
}

}  // namespace sdog
