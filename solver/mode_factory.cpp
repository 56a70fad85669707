#include "solver/mode_factory.h"

#include "geometry/errors.h"
#include "solver/standard_mode.h"
#include "solver/subsolvers_mode.h"

namespace sdog {

std::vector<std::string> mode_names() { return {"standard", "subsolvers"}; }

bool mode_needs_coarse(const std::string&) { return false; }

std::unique_ptr<Mode> make_mode(const std::string& name, DogProblem& problem, const Scenario& scenario,
                                const RunConfig& config) {
  if (name == "standard") return std::make_unique<StandardMode>(problem, scenario, config.standard);
  if (name == "subsolvers") return std::make_unique<SubsolversMode>(problem, scenario, config.subsolvers, config.standard.sqp);
  std::string known;
  for (const auto& n : mode_names()) known += (known.empty() ? "" : ", ") + n;
  throw UsageError("unknown mode '" + name + "' (known: " + known + ")");
}

}  // namespace sdog
