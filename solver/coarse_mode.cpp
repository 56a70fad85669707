#include "solver/coarse_mode.h"

#include "geometry/errors.h"
#include "solver/crease_geometry.h"
#include "solver/curve_interpolation.h"
#include "solver/patch_round.h"
#include "solver/patch_sqp.h"

namespace sdog {

std::string CoarseOptions::validate() const {
  if (!(link_weight >= 0)) return "link_weight must be >= 0";
  return "";
}

CoarseMode::CoarseMode(DogProblem& fine, const DogModel& model, const Scenario& scenario,
                       const CoarseOptions& options, const StandardOptions& standard)
    : fine_(fine), model_(model), scenario_(scenario), options_(options) {
  if (!model.has_coarse) throw UsageError("mode coarse needs the coarse mesh (odd resolutions, not --fine-only)");
  if (!scenario.angles.empty())
    throw UsageError("mode coarse does not support dihedral angle constraints yet (scenario '" + scenario.name +
                     "' has " + std::to_string(scenario.angles.size()) + "); use --mode standard");
  if (scenario.initial.size() > 0)
    throw UsageError("mode coarse cannot start from a given state yet (scenario '" + scenario.name +
                     "'): there is no fine-to-coarse restriction of a deformed state; use another mode");
  const FineCoarseMap& map = model.map;
  // The coarse scenario: the same targets on the coarse twins.
  Scenario coarse_scenario = scenario;
  for (auto& p : coarse_scenario.positions) {
    const int twin = map.fine_to_coarse[p.vertex];
    if (twin < 0)
      throw UsageError("mode coarse: the position constraint on fine vertex " + std::to_string(p.vertex) +
                       " needs a vertex with a coarse twin (a link vertex) for now");
    p.vertex = twin;
  }
  coarse_scenario.curve_signs.resize(model.coarse.stitching.curves.size(), 0.0);  // curves correspond by index
  Weights coarse_weights = fine.weights;
  coarse_weights.link = options.fine_to_coarse ? options.link_weight : 0.0;
  coarse_ = std::make_unique<DogProblem>(model.coarse, model.coarse_topology, coarse_weights);
  // Link blocks (before the solvers fix their patterns): every coarse twin pair, both sides.
  for (int v = 0; v < model.fine.vertex_count(); ++v) {
    const int c = map.fine_to_coarse[v];
    if (c < 0) continue;
    fine_links_.push_back(v);
    coarse_links_.push_back(c);
    fine.link.add({{v, 1.0}});
    coarse_->link.add({{c, 1.0}});
  }
  coarse_mode_ = std::make_unique<StandardMode>(*coarse_, coarse_scenario, standard);
  coarse_x_ = coarse_scenario.start(model.coarse);

  scenario_.install(fine_);
  const auto& fine_curves = model.fine.stitching.curves;
  const auto stencils = coarse_curve_stencils(model);
  for (size_t c = 0; c < fine_curves.size() && c < stencils.size(); ++c)
    for (size_t k = 0; k < fine_curves[c].points.size() && k < stencils[c].size(); ++k)
      for (const EdgePoint& e : model.fine.stitching.points[fine_curves[c].points[k]].copies) {
        crease_targets_.add({{e.v1, e.t}, {e.v2, 1 - e.t}});
        crease_stencils_.push_back(stencils[c][k]);
      }
  std::vector<WeightedTerm> terms = fine_.objective_terms();
  terms[kLink].weight = options_.link_weight;
  terms.push_back({&crease_targets_, 0.5 * fine_.weights.stitching, false});
  for (int p = 0; p < model.fine.patch_count(); ++p)
    patches_.push_back(std::make_unique<PatchSqp>(model.fine, p, terms, fine_.dog, standard.sqp,
                                                  PatchCoupling{&frozen_, {&fine_.fold_bias, &fine_.angles}}));
}

CoarseMode::~CoarseMode() = default;

void CoarseMode::set_time(double t) {
  scenario_.apply(fine_, t);
  coarse_mode_->set_time(t);
}

void CoarseMode::set_coarse_link_targets(const Dofs& x) {
  for (size_t i = 0; i < fine_links_.size(); ++i)
    coarse_->link.set_target(static_cast<int>(i), Eigen::Vector3d(vertex_of(x, fine_links_[i])));
}

void CoarseMode::set_fine_link_targets() {
  for (size_t i = 0; i < coarse_links_.size(); ++i)
    fine_.link.set_target(static_cast<int>(i), Eigen::Vector3d(vertex_of(coarse_x_, coarse_links_[i])));
}

void CoarseMode::prolongate(Dofs& x) const {
  const FineCoarseMap& map = model_.map;
  for (int v = 0; v < model_.fine.vertex_count(); ++v) {
    Eigen::Vector3d p;
    if (map.fine_to_coarse[v] >= 0) {
      p = vertex_of(coarse_x_, map.fine_to_coarse[v]);
    } else if (map.fine_to_coarse_edge[v][0] >= 0) {
      p = 0.5 * (vertex_of(coarse_x_, map.fine_to_coarse_edge[v][0]) + vertex_of(coarse_x_, map.fine_to_coarse_edge[v][1]));
    } else if (map.fine_to_coarse_quad[v] >= 0) {
      p.setZero();
      for (int k = 0; k < 4; ++k) p += 0.25 * vertex_of(coarse_x_, model_.coarse.F(map.fine_to_coarse_quad[v], k));
    } else {
      continue;
    }
    x.segment<3>(3 * v) = p;
  }
}

void CoarseMode::set_crease_targets() {
  const Eigen::MatrixX3d X = to_positions(coarse_x_);
  for (size_t b = 0; b < crease_stencils_.size(); ++b)
    crease_targets_.set_target(static_cast<int>(b), interpolate(model_.coarse, X, crease_stencils_[b]));
}

StepReport CoarseMode::iterate(Dofs& x, bool last) {
  const Dofs x0 = x, coarse0 = coarse_x_;
  if (options_.fine_to_coarse) set_coarse_link_targets(x);
  StepReport report = coarse_mode_->iterate(coarse_x_, last);
  if (report.failed) {
    report.failure = "coarse step: " + report.failure;
    return report;
  }
  set_crease_targets();
  set_fine_link_targets();
  if (options_.prolongate) prolongate(x);
  frozen_ = x;
  if (!step_patch_round(patches_, x, last, report)) {
    x = x0;
    coarse_x_ = coarse0;
    report.failure = "fine step: " + report.failure;
    return report;
  }
  report.folded = check_folded(model_.fine, fine_.sites, x).folded;
  return report;
}

}  // namespace sdog
