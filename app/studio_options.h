#pragma once
// The command line of sdog-studio (also rendered into docs/reference/command-line.md).
#include <CLI/CLI.hpp>
#include <string>

namespace sdog::cli {

struct StudioArgs {
  std::string pattern, res = "auto", mode = "standard", overlay, view = "3d", screenshot,
                       size = "1600x1000";
  int iterations = 0;
  double measure_fps = 0;
  std::string frame, run;  ///< a saved state to open (saved_state.h)
  int iteration = -1;      ///< with `run`; -1: its last frame
};

/// The studio's options, bound to `a`.
void add_studio_options(CLI::App& cli, StudioArgs& a);

/// Throws CLI::ValidationError for option combinations that cannot work (--screenshot or
/// --measure-fps without a pattern or a saved state, both together).
void check_studio_args(const StudioArgs& a);

}  // namespace sdog::cli
