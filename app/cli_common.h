#pragma once
// Shared pieces of the sdog subcommands: pattern/resolution options and the model they build.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "solver/run/run_config.h"

namespace sdog::cli {

/// Options every command that meshes a pattern takes.
struct PatternOptions {
  std::string pattern;
  std::string res = "auto";
  double flatness = 1e-5;
  double merge_fraction = 0.01;
  double snap_fraction = 0.02;
  bool tolerances_given = false;  ///< --merge-tol or --snap-tol was given: cleaning does not adapt
  bool fine_only = false;
  CoarseKind coarse = CoarseKind::kStandard;  ///< sdog mesh --coarse
};

/// Adds PATTERN.svg, --res, --flatness, --merge-tol, --snap-tol, --fine-only to a subcommand
/// (PATTERN `required` or not).
void add_pattern_options(CLI::App& cmd, PatternOptions& o, bool required = true);

/// --iters and --hold of the commands that run a scenario, and whether each was given.
struct ScheduleOptions {
  int iterations = 250;
  int hold = 50;
  CLI::Option* iterations_opt = nullptr;
  CLI::Option* hold_opt = nullptr;
};

/// Adds --iters N (iterations over which the targets move) and --hold N (iterations with the final
/// targets).
void add_schedule_options(CLI::App& cmd, ScheduleOptions& o);

/// The cases of bench and compare: patterns x resolutions, or the thesis grid from patterns_dir.
struct CaseGridArgs {
  std::vector<std::string> patterns;
  std::vector<std::string> resolutions;
  bool thesis_grid = false;
  std::string patterns_dir = "../shared/reference/patterns";
  std::string preset;
};

/// Adds --thesis-grid, --preset and --patterns-dir.
void add_case_grid_options(CLI::App& cmd, CaseGridArgs& a);

/// Adds --preset NAME (the solver settings a run starts from: default or thesis).
void add_preset_option(CLI::App& cmd, std::string& preset);

/// Applies the --preset value to `config` (before its file and the other options); with
/// `thesis_grid` and no --preset, the thesis preset (the thesis grid reproduces the thesis).
void apply_preset_option(const std::string& preset, bool thesis_grid, RunConfig& config);

/// Reads the pattern and builds the model (meshes, topology, map). Throws the library errors.
/// With `warn`, prints the model's warnings (print_warnings).
DogModel build_model(const PatternOptions& o, bool warn = true);

/// The model's warnings (model_warnings) on stderr, one "warning: ..." line each.
void print_warnings(const DogModel& model);

/// argv as one line (for the records a command writes); arguments with spaces, quotes or `$` in
/// single quotes, as a POSIX shell reads them.
std::string command_line_text(int argc, char** argv);

/// Seconds since `start` (steady clock).
double seconds_since(std::chrono::steady_clock::time_point start);

}  // namespace sdog::cli
