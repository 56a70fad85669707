#pragma once
// The run configuration as JSON (`sdog run --config FILE.json`, run.json, workspaces). Every
// unknown key and bad value is an InputError naming the file and the JSON path, e.g. `run.json:
// $.positions[1].end: expected an array of 3 numbers`. The keys that hold one value come from the
// option tables (base/option_table.h); docs/reference/configuration.md is rendered from the same
// tables (reference.h).
#include <nlohmann/json.hpp>
#include <string>

#include "solver/modes/mode_options.h"
#include "solver/problem/weights.h"
#include "solver/run/run_config.h"

namespace sdog {

/// Calls f(key, options, table) for every object of the configuration that an option table
/// describes, in the order of the documentation.
template <class Config, class F>
void for_each_option_section(Config& c, F&& f) {
  f("weights", c.weights, weights_option_table());
  f("solver", c.standard, standard_option_table());
  f("patch_solver", c.subsolvers, subsolver_option_table());
  f("coarse", c.coarse, coarse_option_table());
  f("twolevel", c.twolevel, twolevel_option_table());
  f("admm", c.admm, admm_option_table());
}

/// Overrides the fields present in `json` (an object) and validates the result; `source` names
/// the file in messages.
void apply_run_config(const nlohmann::json& json, const std::string& source, RunConfig& config);
/// Parses a JSON file; InputError "path: cannot open the <what>" or "path: not valid JSON (...)".
nlohmann::json read_json_file(const std::string& path, const std::string& what);
/// Reads and applies a JSON file.
void read_run_config(const std::string& path, RunConfig& config);

/// Every parameter as JSON (run.json, workspaces): read back by apply_run_config, it gives the same
/// configuration.
nlohmann::json to_json(const RunConfig& config);

}  // namespace sdog
