#include "solver/mode_factory.h"

#include <algorithm>
#include <stdexcept>

#include "geometry/errors.h"
#include "geometry/text_format.h"
#include "solver/standard_mode.h"
#include "solver/subsolvers_mode.h"

namespace sdog {

std::vector<std::string> mode_names() { return {"standard", "subsolvers"}; }

std::string known_modes() { return join(mode_names(), ", "); }

void check_mode_name(const std::string& name, const std::string& what) {
  const auto names = mode_names();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw UsageError(what + "unknown mode '" + name + "' (known: " + known_modes() + ")");
}

bool mode_needs_coarse(const std::string&) { return false; }

std::unique_ptr<Mode> make_mode(const std::string& name, DogProblem& problem, const Scenario& scenario,
                                const RunConfig& config) {
  if (name == "standard") return std::make_unique<StandardMode>(problem, scenario, config.standard);
  if (name == "subsolvers") return std::make_unique<SubsolversMode>(problem, scenario, config.subsolvers, config.standard.sqp);
  check_mode_name(name);
  throw std::logic_error("make_mode: mode '" + name + "' is listed but not built");
}

}  // namespace sdog
