#include "solver/modes/mode_factory.h"

#include <stdexcept>

#include "base/errors.h"
#include "solver/modes/admm_mode.h"
#include "solver/modes/coarse_mode.h"
#include "solver/modes/standard_mode.h"
#include "solver/modes/subsolvers_mode.h"
#include "solver/modes/two_level_mode.h"

namespace sdog {
namespace {

const DogModel& required(const DogModel* model, ModeKind mode) {
  if (!model)
    throw std::logic_error(std::string("make_mode: mode ") + enum_name(mode) + " needs the model");
  return *model;
}

}  // namespace

void check_mode_usable(ModeKind mode, const DogModel& model) {
  if (mode_needs_coarse(mode)) CoarseLevel::check_usable(model, mode);
  if (mode != ModeKind::kStandard && model.fine.stitching.has(CurveKind::kSlit))
    throw UsageError(std::string("mode ") + enum_name(mode) +
                     " takes every crease point as one point of the sheet and would close the "
                     "pattern's slits; run patterns with slits in mode standard");
}

std::unique_ptr<Mode> switch_mode(ModeKind mode, DogProblem& problem, const Scenario& scenario,
                                  const ModeOptions& options, const Weights& weights,
                                  const DogModel& model, const Dofs& x, const Dofs* origin) {
  problem.weights = weights;
  auto made = make_mode(mode, problem, scenario, options, &model, origin);
  made->start_from(x);
  return made;
}

std::unique_ptr<Mode> make_mode(ModeKind mode, DogProblem& problem, const Scenario& scenario,
                                const ModeOptions& options, const DogModel* model,
                                const Dofs* origin) {
  const SqpOptions& sqp = options.standard.sqp;
  switch (mode) {
    case ModeKind::kStandard: {
      // The standard mode with exact stitching: the violated rows after a step lie all along the
      // creases, where local restoration steps cost more than the global ones they replace.
      StandardOptions standard = options.standard;
      if (standard.sqp.local_fraction < 0 && standard.stitching == Stitching::kExact)
        standard.sqp.local_fraction = 0;
      return std::make_unique<StandardMode>(problem, scenario, standard,
                                            origin ? std::optional<Dofs>(*origin) : std::nullopt);
    }
    case ModeKind::kSubsolvers:
      return std::make_unique<SubsolversMode>(problem, scenario, options.subsolvers, sqp);
    case ModeKind::kVsAdmm:
      return std::make_unique<AdmmMode>(problem, scenario, AdmmVariant::kVariableSplitting,
                                        options.admm, sqp);
    case ModeKind::kJAdmm:
      return std::make_unique<AdmmMode>(problem, scenario, AdmmVariant::kJacobian, options.admm,
                                        sqp);
    case ModeKind::kProxJAdmm:
      return std::make_unique<AdmmMode>(problem, scenario, AdmmVariant::kProximalJacobian,
                                        options.admm, sqp);
    case ModeKind::kCoarse:
      return std::make_unique<CoarseMode>(problem, required(model, mode), scenario, options.coarse,
                                          options.standard);
    case ModeKind::kTwoLevel:
      return std::make_unique<TwoLevelMode>(problem, required(model, mode), scenario,
                                            options.twolevel, options.standard, options.subsolvers);
  }
  throw std::logic_error("make_mode: unknown mode kind");
}

}  // namespace sdog
