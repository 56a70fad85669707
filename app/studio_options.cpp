#include "app/studio_options.h"

#include "app/versions.h"

#include "solver/modes/mode_kind.h"
#include "ui/vis/layers.h"

namespace sdog::cli {

void add_studio_options(CLI::App& cli, StudioArgs& a) {
  cli.name("sdog-studio");
  cli.description("Scalable DOGs studio: see and steer the solver");
  cli.set_version_flag("--version", version_line("sdog-studio"), "Print the version and exit");
  cli.add_option(
      "PATTERN", a.pattern,
      "crease pattern (SVG or FOLD) to open (with --frame or --run: the run's, from its run.json, "
      "unless given)");
  cli.add_option("--res", a.res,
                 "grid lines XxY (odd values also build the coarse mesh), or auto: 41 along the "
                 "longer side")
      ->capture_default_str();
  cli.add_option("--mode", a.mode, "solver mode (" + known_names<ModeKind>() + ")")
      ->capture_default_str();
  cli.add_option("--overlay", a.overlay,
                 "comma-separated overlays to show instead of vertex-types,wireframe (" +
                     known_names<vis::Layer>() + ")");
  cli.add_option("--view", a.view, "3d, flat or side-by-side")->capture_default_str();
  cli.add_option("--iters", a.iterations,
                 "step the solver N iterations first (from a saved state: N more)")
      ->check(CLI::Range(0, 100000));
  CLI::Option* frame = cli.add_option("--frame", a.frame,
                                      "open this frame of a run (a frame_NNNN.vtu of sdog run "
                                      "--out) on the run's model, mode and settings (from "
                                      "the run.json beside it), at its iteration");
  CLI::Option* run =
      cli.add_option(
             "--run", a.run,
             "open a frame of the run saved in this folder (sdog run --out DIR), by default "
             "its last one; as --frame")
          ->excludes(frame);
  cli.add_option("--iteration", a.iteration,
                 "with --run: the frame of this iteration (one listed in frames.pvd)")
      ->check(CLI::Range(0, 100000000))
      ->needs(run);
  cli.add_option("--screenshot", a.screenshot,
                 "save the window as PNG and exit (needs PATTERN, --frame or --run)");
  cli.add_option("--size", a.size, "window size WIDTHxHEIGHT")->capture_default_str();
  cli.add_option("--measure-fps", a.measure_fps,
                 "play the solver for SECONDS while turning the camera, print the view's frame "
                 "rate and exit "
                 "(needs PATTERN, --frame or --run)")
      ->check(CLI::Range(0.5, 3600.0));
}

void check_studio_args(const StudioArgs& a) {
  const bool opens = !a.pattern.empty() || !a.frame.empty() || !a.run.empty();
  if (!a.screenshot.empty() && !opens)
    throw CLI::ValidationError("--screenshot", "needs PATTERN, --frame or --run");
  if (a.measure_fps > 0 && !opens)
    throw CLI::ValidationError("--measure-fps", "needs PATTERN, --frame or --run");
  if (a.measure_fps > 0 && !a.screenshot.empty())
    throw CLI::ValidationError("--measure-fps", "cannot be combined with --screenshot");
}

}  // namespace sdog::cli
