#include "solver/two_level_mode.h"

#include <cmath>

namespace sdog {
namespace {

SubsolverOptions with_fold_sharpness(SubsolverOptions o, double k) {
  o.fold_sharpness = k;
  return o;
}

}  // namespace

std::string TwoLevelOptions::validate() const {
  if (!(link_weight >= 0)) return "link_weight must be >= 0";
  if (!(fold_sharpness > 0) || !std::isfinite(fold_sharpness)) return "fold_sharpness must be a finite number > 0";
  return "";
}

TwoLevelMode::TwoLevelMode(DogProblem& fine, const DogModel& model, const Scenario& scenario,
                           const TwoLevelOptions& options, const StandardOptions& standard,
                           const SubsolverOptions& subsolvers)
    : coarse_(fine, model, scenario, options.link_weight, standard, "twolevel", options.fold_sharpness),
      fine_(fine, scenario, with_fold_sharpness(subsolvers, options.fold_sharpness), standard.sqp) {}

void TwoLevelMode::set_time(double t) {
  coarse_.set_time(t);
  fine_.set_time(t);
}

void TwoLevelMode::start_from(const Dofs& x) { coarse_.start_from(x); }

StepReport TwoLevelMode::iterate(Dofs& x, bool last) {
  const Dofs x0 = x, c0 = coarse_.state();
  StepReport coarse = coarse_.step(x);
  if (coarse.failed) {
    coarse.failure = "coarse step: " + coarse.failure;
    return coarse;
  }
  const Prolongation& P = coarse_.prolongation();
  x += P.apply(coarse_.state()) - P.apply(c0);
  StepReport report = fine_.iterate(x, last);
  if (report.failed) {
    x = x0;
    coarse_.set_state(c0);
    report.failure = "fine step: " + report.failure;
    return report;
  }
  report.sqp_steps += coarse.sqp_steps;
  report.factorizations += coarse.factorizations;
  report.restoration_steps += coarse.restoration_steps;
  report.fold_retries += coarse.fold_retries;
  report.factor_ms += coarse.factor_ms;
  return report;
}

}  // namespace sdog
