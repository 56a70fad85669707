#pragma once
// Everything a deformation run is set up from: the scenario, its iteration counts, weights and
// mode options, extra position and angle constraints and mode switches. Plain data; read from a
// JSON file by the configuration layer (solver/config/run_config_json.h), checked by
// validate_run_config, turned into a scenario on a mesh by make_scenario (run_setup.h).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "base/enum_names.h"
#include "base/errors.h"
#include "base/option_table.h"
#include "geometry/pattern/crease_pattern.h"
#include "solver/modes/mode_kind.h"
#include "solver/modes/mode_options.h"
#include "solver/problem/weights.h"

namespace sdog {

/// The scenarios of `sdog run --scenario` (problem/scenario.h and flatten_scenario.h).
enum class ScenarioKind { kCorners, kFold, kNone, kFlatten };
template <>
struct EnumNames<ScenarioKind> {
  static constexpr const char* noun = "scenario";
  static constexpr EnumName<ScenarioKind> rows[] = {
      {ScenarioKind::kCorners, "corners"},
      {ScenarioKind::kFold, "fold"},
      {ScenarioKind::kNone, "none"},
      {ScenarioKind::kFlatten, "flatten"},
  };
};

/// Named sets of solver settings. kDefault: exact stitching, a polish with a factorisation
/// budget. kThesis: the thesis's solver, for reproducing its numbers: soft stitching (weight 10), a
/// polish without a budget and a projection of kThesisProjectionSteps steps per phase, one step per
/// iteration, the fold bias up to 1e14 and the angle weight 1000.
enum class Preset { kDefault, kThesis };
template <>
struct EnumNames<Preset> {
  static constexpr const char* noun = "preset";
  static constexpr EnumName<Preset> rows[] = {
      {Preset::kDefault, "default"},
      {Preset::kThesis, "thesis"},
  };
};

/// A position constraint before it is resolved against a mesh.
struct PositionSpec {
  std::string path;           ///< source and JSON path, for messages
  std::optional<int> vertex;  ///< fine vertex index ...
  std::optional<Eigen::Vector2d>
      near;  ///< ... or the vertex nearest this flat-state point (sheet units)
  std::optional<Eigen::Vector3d> start;  ///< mesh units; default: the vertex's flat position
  std::optional<Eigen::Vector3d> end;    ///< absolute target, mesh units ...
  std::optional<Eigen::Vector3d> move;   ///< ... or displacement from start
};

/// An angle constraint before it is resolved: one crease point, or every fold site of a curve
/// (named by its index among the cleaned creases or by its SVG element id).
struct AngleSpec {
  std::string path;  ///< source and JSON path, for messages
  std::optional<int> point;
  std::optional<int> curve;
  std::optional<std::string> id;
  double start_degrees = 0;
  double end_degrees = 0;
};

/// A crease's assignment and fold angle, set by the configuration over the drawing's: for the
/// crease with index `curve` among the cleaned creases (as `sdog mesh` lists them), or for every
/// cleaned crease drawn by the SVG element `id`.
struct CreaseSetting {
  std::string path;  ///< source and JSON path, for messages
  std::optional<int> curve;
  std::optional<std::string> id;
  std::optional<Fold> fold;
  std::optional<double> angle;  ///< degrees, 0 to 180
  bool operator==(const CreaseSetting& o) const {
    return path == o.path && curve == o.curve && id == o.id && fold == o.fold && angle == o.angle;
  }
};

/// From iteration `iteration` on (1-based), mode `mode` computes the run (`sdog run --switch`).
struct ModeSwitch {
  int iteration = 1;
  ModeKind mode = ModeKind::kStandard;
};

/// The thesis's weight of its dihedral-angle term (the default is Weights::angles).
constexpr double kThesisAngleWeight = 1000;
/// The thesis preset's projection_steps: without a factorisation budget, this bounds its last
/// iteration where the projection stalls.
constexpr int kThesisProjectionSteps = 100;

/// The run's configuration: the options of every mode (ModeOptions) and what the run asks for.
struct RunConfig : ModeOptions {
  Preset preset = Preset::kDefault;                ///< the preset the solver options started from
  ScenarioKind scenario = ScenarioKind::kCorners;  ///< kNone: only the listed constraints
  int iterations = 250;                            ///< iterations over which targets move
  int hold = 50;                                   ///< iterations with the final targets
  double fold_angle =
      90;  ///< degrees: the fold scenario's final dihedral angle, the flatten scenario's start
  double fold_percent =
      100;  ///< how far the fold scenario folds: this share of every crease's angle
  Weights weights;
  std::vector<PositionSpec> positions;
  std::vector<AngleSpec> angles;
  std::vector<CreaseSetting> creases;
  std::vector<ModeSwitch> switches;  ///< mode switches during the run, by ascending iteration
};

/// Sets the options and weights a preset decides (the others keep their values).
void apply_preset(Preset preset, RunConfig& config);

/// The keys of the configuration's top level that hold one value: scenario, iterations, hold,
/// angle.
const OptionTable<RunConfig>& run_option_table();

/// Checks the values: an Error of `kind` ("source: $.path: why"); kUsage when they all come from
/// the command line, kInput when a configuration file gave some.
void validate_run_config(const RunConfig& config, const std::string& source,
                         ErrorKind kind = ErrorKind::kInput);

}  // namespace sdog
