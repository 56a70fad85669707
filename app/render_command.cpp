// sdog render: headless pictures of a meshed pattern with overlays: at rest, after a solver run, or
// at a state a run saved (--frame, --run).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/saved_state.h"
#include "base/atomic_output.h"
#include "base/errors.h"
#include "solver/run/run_setup.h"
#include "ui/vis/picture.h"

namespace sdog::cli {
namespace {

struct RenderArgs {
  PatternOptions pattern;
  std::string overlay = "vertex-types,crease-curves,wireframe";
  std::string view = "side-by-side";
  bool coarse = false;
  std::string mode = "standard";
  std::string scenario = "corners";
  int iterations = 0;
  CLI::Option* iterations_opt = nullptr;
  std::string frame, run;
  int iteration = 0;
  CLI::Option *iteration_opt = nullptr, *scenario_opt = nullptr, *caption_opt = nullptr;
  CLI::App* command = nullptr;
  std::string size = "1600x800";
  std::string camera;
  std::string caption;
  std::string out;
  bool transparent = false;
  std::string style = "standard";
  std::string effects = "ambient-occlusion";
  CLI::Option* overlay_opt = nullptr;
};

// What a picture draws: the model, its state and the caption naming them.
struct Drawing {
  DogModel model;
  vis::SceneState state;
  std::string caption;
};

bool has_layer(const std::vector<vis::Layer>& layers, vis::Layer layer) {
  return std::find(layers.begin(), layers.end(), layer) != layers.end();
}

std::string overlay_help() {
  std::string help =
      "comma-separated overlays (at most one of vertex-types, patches, dog-residual, edge-strain, "
      "bending, which colour the mesh):";
  for (vis::Layer l : enum_values<vis::Layer>())
    help += std::string("\n  ") + enum_name(l) + ": " + vis::layer_description(l);
  return help;
}

// The last state of a run of `mode` over the configuration's scenario, with the constraints at
// their final targets. Throws SolverError (naming the iteration and the cause) when the run fails.
vis::SceneState run_state(const DogModel& model, ModeKind mode, const RunConfig& config) {
  RunSetup setup(model, mode, config);
  const RunSummary summary = setup.run({});
  if (summary.failed())
    throw SolverError(std::string("the solver (") + enum_name(mode) + ") failed at " +
                      summary.failure);
  return vis::scene_state(setup.problem(), setup.positions(), setup.mode().coarse_positions(),
                          &setup.scenario(), 1);
}

// The pattern at rest, or after a run of --iters iterations.
Drawing fresh_drawing(const RenderArgs& a, const std::vector<vis::Layer>& layers) {
  const bool run = a.iterations_opt->count() > 0;
  RunConfig config;
  config.scenario = parse_enum<ScenarioKind>(a.scenario, "--scenario: ");
  config.iterations = a.iterations;
  config.hold = 0;
  const ModeKind mode = parse_enum<ModeKind>(a.mode, "--mode: ");
  if (run) validate_run_config(config, "command line", ErrorKind::kUsage);
  Drawing d{build_model(a.pattern), {}, ""};
  d.caption =
      std::filesystem::path(a.pattern.pattern).stem().string() + " " + d.model.fine_res.str();
  if (run) {
    d.state = run_state(d.model, mode, config);
    d.caption +=
        ", " + a.mode + ", " + std::to_string(a.iterations) + " iterations of " + a.scenario;
  } else if (has_layer(layers, vis::Layer::kHandles)) {
    const Scenario scenario = make_scenario(config, d.model.fine);
    d.state = vis::rest_scene_state(d.model, &scenario);
    d.caption += ", targets of " + a.scenario;
  } else {
    d.state = vis::rest_scene_state(d.model);
  }
  return d;
}

// The state a run saved (--frame, or --run with --iteration), on the model it belongs to.
Drawing saved_drawing(const RenderArgs& a, const std::vector<vis::Layer>& layers) {
  SavedStateRequest request;
  request.frame = a.frame;
  request.run = a.run;
  if (a.iteration_opt->count()) request.iteration = a.iteration;
  request.command_line = a.pattern;
  request.given = [&a](const std::string& option) { return a.command->count(option) > 0; };
  const SavedState saved = load_saved_state(request);
  if (saved.run && a.scenario_opt->count())
    throw UsageError("--scenario: a saved state is drawn with its run's scenario (" +
                     std::string(enum_name(saved.run->config.scenario)) + ", from " +
                     saved.run->record + "); leave --scenario out");
  const bool handles = has_layer(layers, vis::Layer::kHandles);
  const RunConfig config =
      saved_state_config(saved, parse_enum<ScenarioKind>(a.scenario, "--scenario: "));
  Drawing d{saved_state_model(saved), {}, ""};
  d.state = saved_scene_state(saved, d.model, config, handles);
  d.caption =
      std::filesystem::path(saved.pattern.pattern).stem().string() + " " + d.model.fine_res.str();
  const std::string when = saved.iteration ? "iteration " + std::to_string(*saved.iteration)
                                           : std::filesystem::path(saved.frame).filename().string();
  if (saved.run)
    d.caption += ", " + saved.run->mode_at(saved.iteration.value_or(0)) + ", " + when + " of " +
                 enum_name(config.scenario);
  else
    d.caption +=
        ", " + when + (handles ? std::string(", targets of ") + enum_name(config.scenario) : "");
  return d;
}

void render(const RenderArgs& a) {
  const bool saved = !a.frame.empty() || !a.run.empty();
  if (!saved && a.pattern.pattern.empty())
    throw UsageError(
        "give the crease PATTERN, or a state a run saved with --frame FILE.vtu or --run DIR");
  vis::PictureOptions options;
  options.size = vis::parse_image_size(a.size);
  options.paper = a.style == "paper";
  // The paper style draws the crease curves alone unless overlays are asked for.
  options.layers =
      vis::parse_layers(options.paper && a.overlay_opt->count() == 0 ? "crease-curves" : a.overlay);
  options.effects = vis::parse_paper_effects(a.effects);
  options.scene.view = parse_enum<vis::View>(a.view);
  options.scene.coarse = a.coarse;
  options.transparent = a.transparent;
  parse_enum<ModeKind>(a.mode, "--mode: ");
  parse_enum<ScenarioKind>(a.scenario, "--scenario: ");
  if (!a.camera.empty()) options.camera = vis::load_camera(a.camera);
  // Fail on a missing display or an unusable output directory before the work.
  vis::require_display();
  const std::filesystem::path target(a.out);
  OutputSet out(target.has_parent_path() ? target.parent_path().string() : ".");

  const Drawing d = saved ? saved_drawing(a, options.layers) : fresh_drawing(a, options.layers);
  options.caption = a.caption_opt->count() ? a.caption : d.caption;
  vis::render_picture(d.model, d.state, options, out.temporary(target.filename().string()));
  for (const auto& f : out.commit()) std::cout << "wrote " << f << "\n";
}

}  // namespace

void register_render_command(CLI::App& app, Runner& run) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd =
      app.add_subcommand("render",
                         "Render the meshed pattern with overlays offscreen to PNG: at rest, after "
                         "a solver run, or at a state a run "
                         "saved (needs an X display: use xvfb-run on a headless machine)");
  args->command = cmd;
  add_pattern_options(*cmd, args->pattern, false);
  args->overlay_opt =
      cmd->add_option("--overlay", args->overlay, overlay_help())->capture_default_str();
  cmd->add_option("--view", args->view,
                  "3d: current positions seen from the front right, above; flat: the rest state "
                  "seen from above; "
                  "side-by-side: fine (left) and coarse (right) meshes seen from above")
      ->capture_default_str();
  cmd->add_flag("--coarse", args->coarse,
                "3d and flat views: draw the coarse mesh's edges over the fine mesh");
  args->iterations_opt =
      cmd->add_option("--iters", args->iterations,
                      "first run the solver for N iterations of the scenario (targets reach "
                      "their end at iteration N), then draw the last state")
          ->check(CLI::Range(1, 1000000));
  CLI::Option* frame = cmd->add_option("--frame", args->frame,
                                       "draw this frame of a run (a frame_NNNN.vtu of sdog run "
                                       "--out) instead of running; PATTERN, "
                                       "--res and the mesh options come from the run.json beside "
                                       "it unless given (then the frame "
                                       "must be of that mesh)")
                           ->excludes(args->iterations_opt);
  CLI::Option* run_dir =
      cmd->add_option("--run", args->run,
                      "draw a frame of the run saved in this folder (sdog run --out DIR), by "
                      "default its last one; as --frame")
          ->excludes(args->iterations_opt)
          ->excludes(frame);
  args->iteration_opt =
      cmd->add_option("--iteration", args->iteration,
                      "with --run: the frame of this iteration (one listed in frames.pvd)")
          ->check(CLI::Range(0, 100000000))
          ->needs(run_dir);
  cmd->add_option("--mode", args->mode, "solver mode of the run (" + known_names<ModeKind>() + ")")
      ->capture_default_str()
      ->needs(args->iterations_opt);
  args->scenario_opt =
      cmd->add_option("--scenario", args->scenario,
                      "scenario of the run, and whose targets the handles overlay shows without a "
                      "run (a saved state: its run's scenario)")
          ->check(CLI::IsMember(enum_names<ScenarioKind>()))
          ->capture_default_str();
  cmd->add_option("--size", args->size, "image size WIDTHxHEIGHT in pixels")->capture_default_str();
  cmd->add_option(
      "--camera", args->camera,
      "camera pose (JSON: position, focal_point, view_up, view_angle, parallel, parallel_scale, "
      "window_center; as the studio saves it) instead of the view's default camera");
  args->caption_opt = cmd->add_option(
      "--caption", args->caption,
      "text at the top left instead of the pattern, resolution and run ('' for none)");
  cmd->add_option("--out", args->out, "PNG file to write")->required();
  cmd->add_flag("--transparent", args->transparent, "transparent background");
  cmd->add_option("--style", args->style,
                  "standard: the debugging view (legends, caption, dots); paper: a figure for a "
                  "publication (smooth "
                  "paper-coloured surface, crease curves coloured by assignment, a light kit, "
                  "antialiasing, no "
                  "legends or caption; overlays: crease-curves unless --overlay says otherwise)")
      ->check(CLI::IsMember({"standard", "paper"}))
      ->capture_default_str();
  cmd->add_option("--effects", args->effects,
                  "paper style: the render effect, ambient-occlusion (darkens the insides of "
                  "folds), shadows (hard shadows of the key light) or none")
      ->capture_default_str();
  cmd->callback([args, &run]() { run = [args]() { render(*args); }; });
}

}  // namespace sdog::cli
