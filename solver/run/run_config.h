#pragma once
// Everything a deformation run is set up from: the scenario, its iteration counts, weights and
// solver options, and extra position and angle constraints. Read from a JSON file (see the README,
// "Run configuration"); every unknown key and bad value is an InputError naming the file and the
// JSON path, e.g. `run.json: $.positions[1].end: expected an array of 3 numbers`.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "solver/modes/admm_mode.h"
#include "solver/problem/scenario.h"
#include "solver/modes/coarse_mode.h"
#include "solver/modes/two_level_mode.h"
#include "solver/modes/standard_mode.h"
#include "solver/modes/subsolvers_mode.h"

namespace sdog {

/// A position constraint before it is resolved against a mesh.
struct PositionSpec {
  std::string path;                      ///< source and JSON path, for messages
  std::optional<int> vertex;             ///< fine vertex index ...
  std::optional<Eigen::Vector2d> near;   ///< ... or the vertex nearest this flat-state point (sheet units)
  std::optional<Eigen::Vector3d> start;  ///< mesh units; default: the vertex's flat position
  std::optional<Eigen::Vector3d> end;    ///< absolute target, mesh units ...
  std::optional<Eigen::Vector3d> move;   ///< ... or displacement from start
};

/// An angle constraint before it is resolved: one crease point, or every fold site of a curve.
struct AngleSpec {
  std::string path;  ///< source and JSON path, for messages
  std::optional<int> point;
  std::optional<int> curve;
  double start_degrees = 0;
  double end_degrees = 0;
};

/// From iteration `iteration` on (1-based), mode `mode` computes the run (`sdog run --switch`).
struct ModeSwitch {
  int iteration = 1;
  std::string mode;
};

/// The scenario names `make_scenario` knows (`sdog run --scenario`, `sdog compare --scenario`, the
/// "scenario" key of a configuration file), in the order of the documentation.
std::vector<std::string> scenario_names();
/// Throws UsageError "`what`unknown scenario 'name' (known: ...)" unless `name` is a scenario.
void check_scenario_name(const std::string& name, const std::string& what = "");

struct RunConfig {
  std::string scenario = "corners";  ///< one of scenario_names(); none: only the listed constraints
  int iterations = 250;              ///< iterations over which targets move
  int hold = 50;                     ///< iterations with the final targets
  double fold_angle = 90;            ///< degrees, the fold scenario's final dihedral angle
  Weights weights;
  StandardOptions standard;
  SubsolverOptions subsolvers;  ///< the multi-patch modes' per-patch solves
  CoarseOptions coarse;         ///< the coarse mode
  std::vector<PositionSpec> positions;
  std::vector<AngleSpec> angles;
  AdmmOptions admm;  ///< the ADMM modes (vsadmm, jadmm, proxjadmm)
  TwoLevelOptions twolevel;  ///< the twolevel mode
  std::vector<ModeSwitch> switches;  ///< mode switches during the run, by ascending iteration
};

/// Overrides the fields present in `json` (an object); `source` names the file in messages.
void apply_run_config(const nlohmann::json& json, const std::string& source, RunConfig& config);
/// Parses a JSON file; InputError "path: cannot open the <what>" or "path: not valid JSON (...)".
nlohmann::json read_json_file(const std::string& path, const std::string& what);
/// Reads and applies a JSON file.
void read_run_config(const std::string& path, RunConfig& config);
/// Checks the values (InputError naming the field).
void validate_run_config(const RunConfig& config, const std::string& source);

/// The scenario on a fine mesh: the named one plus the listed constraints. Throws InputError for
/// vertex or crease-point indices that do not exist (naming the JSON path).
Scenario make_scenario(const RunConfig& config, const DogMesh& mesh);

/// Throws UsageError when the scenario has no targets (the fold scenario on a pattern without fold
/// sites at this resolution, `none` without constraints); `where` names the pattern and resolution.
void check_scenario_targets(const Scenario& scenario, const RunConfig& config, const std::string& where);

/// Every parameter as JSON (for run.json).
nlohmann::json to_json(const RunConfig& config);

}  // namespace sdog
