#include "app/studio_options.h"

#include "solver/modes/mode_kind.h"
#include "ui/vis/layers.h"

namespace sdog::cli {

void add_studio_options(CLI::App& cli, StudioArgs& a) {
  cli.name("sdog-studio");
  cli.description("Scalable DOGs studio: see and steer the solver");
  cli.add_option("PATTERN", a.pattern, "crease pattern (SVG or FOLD) to open");
  cli.add_option("--res", a.res, "grid lines XxY (odd values also build the coarse mesh), or auto: 41 along the longer side")
      ->capture_default_str();
  cli.add_option("--mode", a.mode, "solver mode (" + known_modes() + ")")->capture_default_str();
  cli.add_option("--overlay", a.overlay,
                 "comma-separated overlays to show instead of vertex-types,wireframe (" + vis::known_layers() + ")");
  cli.add_option("--view", a.view, "3d, flat or side-by-side")->capture_default_str();
  cli.add_option("--iters", a.iterations, "step the solver N iterations first")->check(CLI::Range(0, 100000));
  cli.add_option("--screenshot", a.screenshot, "save the window as PNG and exit (needs PATTERN)");
  cli.add_option("--size", a.size, "window size WIDTHxHEIGHT")->capture_default_str();
  cli.add_option("--measure-fps", a.measure_fps,
                 "play the solver for SECONDS while turning the camera, print the view's frame rate and exit "
                 "(needs PATTERN)")
      ->check(CLI::Range(0.5, 3600.0));
}

void check_studio_args(const StudioArgs& a) {
  if (!a.screenshot.empty() && a.pattern.empty()) throw CLI::ValidationError("--screenshot", "needs PATTERN");
  if (a.measure_fps > 0 && a.pattern.empty()) throw CLI::ValidationError("--measure-fps", "needs PATTERN");
  if (a.measure_fps > 0 && !a.screenshot.empty())
    throw CLI::ValidationError("--measure-fps", "cannot be combined with --screenshot");
}

}  // namespace sdog::cli
