#pragma once
// The record `sdog run --out DIR` keeps of a run in DIR/run.json, read back so that its frames can
// be drawn on the model they were computed on: the pattern file, the resolution and mesh options,
// the mode and the run configuration.
#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_common.h"
#include "solver/run/run_config.h"

namespace sdog::cli {

/// Adds the keys of run.json that rebuild the run's model besides "pattern" and "resolution":
/// "pattern_path" (the pattern file's absolute path) and "mesh_options" ("flatness", "merge_tol",
/// "snap_tol", "fine_only").
void add_model_record(nlohmann::json& run_json, const PatternOptions& pattern);

struct SavedRun {
  std::string record;  ///< the run.json file
  PatternOptions
      pattern;       ///< the pattern file, the fine resolution and the mesh options of the run
  std::string mode;  ///< the mode the run started with
  RunConfig config;

  /// The mode computing iteration k (the start mode, or the last switch at or before k).
  std::string mode_at(int iteration) const;
};

/// Reads a run.json. Throws InputError naming the file and the JSON path of a missing or bad
/// value. The pattern is "pattern_path", or "pattern" (relative to the working directory) when only
/// that one exists; a record without "mesh_options" gets the default ones.
SavedRun read_saved_run(const std::string& path);

}  // namespace sdog::cli
