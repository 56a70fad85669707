#include "solver/modes/mode_factory.h"

#include <algorithm>
#include <stdexcept>

#include "base/errors.h"
#include "base/text_format.h"
#include "solver/modes/admm_mode.h"
#include "solver/modes/coarse_mode.h"
#include "solver/modes/standard_mode.h"
#include "solver/modes/subsolvers_mode.h"
#include "solver/modes/two_level_mode.h"

namespace sdog {

std::vector<std::string> mode_names() { return {"standard", "subsolvers", "vsadmm", "jadmm", "proxjadmm", "coarse", "twolevel"}; }

std::string known_modes() { return join(mode_names(), ", "); }

void check_mode_name(const std::string& name, const std::string& what) {
  const auto names = mode_names();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw UsageError(what + "unknown mode '" + name + "' (known: " + known_modes() + ")");
}

bool mode_needs_coarse(const std::string& name) { return name == "coarse" || name == "twolevel"; }

void check_mode_usable(const std::string& name, const DogModel& model) {
  check_mode_name(name);
  if (mode_needs_coarse(name)) CoarseLevel::check_usable(model, name);
}

std::unique_ptr<Mode> switch_mode(const std::string& name, DogProblem& problem, const Scenario& scenario,
                                  const RunConfig& config, const DogModel& model, const Dofs& x) {
  problem.weights = config.weights;
  auto mode = make_mode(name, problem, scenario, config, &model);
  mode->start_from(x);
  return mode;
}

ModeSchedule switch_schedule(DogProblem& problem, const Scenario& scenario, const RunConfig& config,
                             const DogModel& model, std::unique_ptr<Mode>& current) {
  return [&, next = size_t{0}](int k, const Dofs& x) mutable -> Mode* {
    if (next >= config.switches.size() || config.switches[next].iteration != k) return nullptr;
    current = switch_mode(config.switches[next++].mode, problem, scenario, config, model, x);
    return current.get();
  };
}

std::unique_ptr<Mode> make_mode(const std::string& name, DogProblem& problem, const Scenario& scenario,
                                const RunConfig& config, const DogModel* model) {
  if (name == "standard") return std::make_unique<StandardMode>(problem, scenario, config.standard);
  if (name == "subsolvers") return std::make_unique<SubsolversMode>(problem, scenario, config.subsolvers, config.standard.sqp);
  if (name == "coarse") {
    if (!model) throw std::logic_error("make_mode: mode coarse needs the model");
    return std::make_unique<CoarseMode>(problem, *model, scenario, config.coarse, config.standard);
  }
  if (name == "twolevel") {
    if (!model) throw std::logic_error("make_mode: mode twolevel needs the model");
    return std::make_unique<TwoLevelMode>(problem, *model, scenario, config.twolevel, config.standard,
                                          config.subsolvers);
  }
  for (const auto& [admm, variant] : {std::pair{"vsadmm", AdmmVariant::kVariableSplitting},
                                      std::pair{"jadmm", AdmmVariant::kJacobian},
                                      std::pair{"proxjadmm", AdmmVariant::kProximalJacobian}})
    if (name == admm) return std::make_unique<AdmmMode>(problem, scenario, variant, config.admm, config.standard.sqp);
  check_mode_name(name);
  throw std::logic_error("make_mode: mode '" + name + "' is listed but not built");
}

}  // namespace sdog
