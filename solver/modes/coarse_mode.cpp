#include "solver/modes/coarse_mode.h"

#include "solver/modes/patch_round.h"
#include "solver/multilevel/curve_interpolation.h"
#include "solver/patches/patch_sqp.h"
#include "solver/terms/crease_geometry.h"

namespace sdog {

CoarseMode::CoarseMode(DogProblem& fine, const DogModel& model, const Scenario& scenario,
                       const CoarseOptions& options, const StandardOptions& standard)
    : fine_(fine), model_(model), scenario_(scenario), options_(options) {
  coarse_ = std::make_unique<CoarseLevel>(fine, model, scenario,
                                          options.fine_to_coarse ? options.link_weight : 0.0,
                                          standard, ModeKind::kCoarse);
  projection_ = std::make_unique<FinalProjection>(fine, standard.sqp);
  // Fine link blocks (before the solvers fix their patterns): every coarse twin pair.
  fine.link.clear();  // a mode that ran on this problem before may have made them
  for (const auto& [v, c] : coarse_->links()) fine.link.add({{v, 1.0}});
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
    patches_.push_back(
        std::make_unique<PatchSqp>(model.fine, p, terms, fine_.dog, standard.sqp,
                                   PatchCoupling{&frozen_, fine_.cross_patch_terms()}));
}

CoarseMode::~CoarseMode() = default;

const Dofs& CoarseMode::coarse_state() const {
  return coarse_->state();
}

void CoarseMode::set_time(double t) {
  scenario_.apply(fine_, t);
  coarse_->set_time(t);
}

void CoarseMode::start_from(const Dofs& x) {
  coarse_->start_from(x);
}

void CoarseMode::set_fine_link_targets() {
  const auto& links = coarse_->links();
  for (size_t i = 0; i < links.size(); ++i)
    fine_.link.set_target(static_cast<int>(i),
                          Eigen::Vector3d(vertex_of(coarse_->state(), links[i].second)));
}

void CoarseMode::set_crease_targets() {
  const Eigen::MatrixX3d X = to_positions(coarse_->state());
  for (size_t b = 0; b < crease_stencils_.size(); ++b)
    crease_targets_.set_target(static_cast<int>(b),
                               interpolate(model_.coarse, X, crease_stencils_[b]));
}

StepReport CoarseMode::iterate(const IterationContext& ctx, Dofs& x) {
  set_time(ctx.t);
  const bool last = ctx.last();
  const Dofs x0 = x, coarse0 = coarse_->state();
  StepReport report = coarse_->step(x);
  if (report.failed) {
    report.failure = "coarse step: " + report.failure;
    return report;
  }
  set_crease_targets();
  set_fine_link_targets();
  if (options_.prolongate) x = coarse_->prolongation().apply(coarse_->state());
  frozen_ = x;
  bool fine_ok = false;
  coarse_->run_beside([&] { fine_ok = step_patch_round(patches_, x, false, report); },
                      options_.concurrent_coarse && !last ? ctx.next_t : std::nullopt);
  if (!fine_ok || (last && !projection_->project(x, report))) {
    x = x0;
    coarse_->set_state(coarse0);
    report.failure = "fine step: " + report.failure;
    return report;
  }
  report.folded = check_folded(model_.fine, fine_.free_sites, x).folded;
  return report;
}

}  // namespace sdog
