#include "solver/modes/coarse_level.h"

#include <tbb/parallel_invoke.h>

#include "base/errors.h"
#include "solver/multilevel/restriction.h"
#include "solver/sqp/sqp_solver.h"
#include "solver/terms/crease_geometry.h"

namespace sdog {
namespace {

const DogModel& checked(const DogModel& model, ModeKind mode) {
  CoarseLevel::check_usable(model, mode);
  return model;
}

}  // namespace

void CoarseLevel::check_usable(const DogModel& model, ModeKind mode) {
  if (!model.has_coarse)
    throw UsageError(std::string("mode ") + enum_name(mode) +
                     " needs the coarse mesh (odd resolutions, not --fine-only)");
}

CoarseLevel::CoarseLevel(const DogProblem& fine, const DogModel& model, const Scenario& scenario,
                         double link_weight, const StandardOptions& standard, ModeKind mode,
                         double fold_sharpness)
    : model_(model), link_weight_(link_weight), prolongation_(checked(model, mode)) {
  const FineCoarseMap& map = model.map;
  Scenario coarse_scenario = scenario;
  coarse_scenario.positions.clear();
  for (const auto& p : scenario.positions) {
    if (map.fine_to_coarse[p.vertex] >= 0)
      coarse_scenario.positions.push_back({map.fine_to_coarse[p.vertex], p.start, p.end});
    else
      carried_.push_back(p);
  }
  // An angle constraint at a fine crease point whose coarse twin is a fold site constrains the twin
  // to the same dihedral angle; one at a fine-only crease point acts on the fine mesh only.
  coarse_scenario.angles.clear();
  const std::vector<int> crease_twin = coarse_crease_twins(model);
  const std::vector<FoldSite> coarse_sites = fold_sites(model.coarse);
  for (const AngleConstraint& a : scenario.angles) {
    const int c = crease_twin[a.point];
    if (c >= 0 && find_fold_site(coarse_sites, c))
      coarse_scenario.angles.push_back({c, a.start_degrees, a.end_degrees});
  }
  coarse_scenario.curve_signs.resize(model.coarse.stitching.curves.size(),
                                     0.0);  // curves correspond by index
  Weights weights = fine.weights;
  weights.link = link_weight;
  weights.edge_points = weights.positions;  // the carried position targets
  problem_ =
      std::make_unique<DogProblem>(model.coarse, model.coarse_topology, weights, fold_sharpness);
  // Blocks before the solver fixes its pattern.
  for (const auto& p : carried_) problem_->edge_points.add(prolongation_.row(p.vertex));
  for (int v = 0; v < model.fine.vertex_count(); ++v)
    if (map.fine_to_coarse[v] >= 0) {
      links_.push_back({v, map.fine_to_coarse[v]});
      problem_->link.add({{map.fine_to_coarse[v], 1.0}});
    }
  // One BLAS thread: the step may run beside the fine patch solves (run_beside), and its result
  // must not depend on whether it did (OpenBLAS rounds differently with another thread count).
  StandardOptions options = standard;
  options.blas_threads = 1;
  // The coarse step follows the fine targets one step per iteration, as in the thesis: the fine
  // mesh, not the coarse one, is what converges.
  options.converge = false;
  mode_ = std::make_unique<StandardMode>(*problem_, coarse_scenario, options);
  set_time(0);
  if (scenario.initial.size() > 0)
    start_from(scenario.initial);
  else
    x_ = coarse_scenario.start(model.coarse);
}

void CoarseLevel::start_from(const Dofs& fine_x) {
  ahead_.reset();
  x_ = restrict_to_coarse(model_, fine_x);
  mode_->start_from(x_);
  mode_->sqp().restore_constraints(x_);  // the restriction is close to a DOG, not on it
  // At slightly folded creases the restriction can leave coarse fold sites on the wrong side (the
  // fold test reads the crease's osculating plane from second differences of crease points 2 fine
  // cells apart); the fold bias then makes the coarse step fail. The coarse mesh then follows the
  // fine folds through the link targets instead of folding on its own.
  if (!check_folded(model_.coarse, problem_->free_sites, x_).folded) mode_->set_folding(false);
}

CoarseLevel::~CoarseLevel() = default;

void CoarseLevel::set_time(double t) {
  t_ = t;
  mode_->set_time(t);
  for (size_t k = 0; k < carried_.size(); ++k)
    problem_->edge_points.set_target(static_cast<int>(k),
                                     carried_[k].start + t * (carried_[k].end - carried_[k].start));
}

StepReport CoarseLevel::step(const Dofs& fine_x) {
  if (ahead_ && ahead_->t == t_) {
    StepReport report = std::move(ahead_->report);
    if (!report.failed) x_ = std::move(ahead_->x);  // a failed step left the state as it was
    ahead_.reset();
    ++taken_ahead_;
    return report;
  }
  // A step computed for another time (never in a run: its times are known in advance) is dropped;
  // the multipliers of the coarse solver keep what it did.
  ahead_.reset();
  if (link_weight_ > 0)
    for (size_t i = 0; i < links_.size(); ++i)
      problem_->link.set_target(static_cast<int>(i),
                                Eigen::Vector3d(vertex_of(fine_x, links_[i].first)));
  return mode_->step(x_, false);
}

void CoarseLevel::run_beside(const std::function<void()>& work, std::optional<double> next_time) {
  ahead_.reset();
  if (!next_time || !can_step_ahead()) return work();
  auto step_ahead = [&] {
    set_time(*next_time);
    Ahead a{*next_time, x_, {}};
    a.report = mode_->step(a.x, false);
    ahead_ = std::move(a);
  };
  tbb::parallel_invoke(work, step_ahead);
}

}  // namespace sdog
