// sdog render: headless pictures of a meshed pattern with overlays, optionally after a solver run.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "base/atomic_output.h"
#include "base/errors.h"
#include "solver/run/run_setup.h"
#include "ui/vis/picture.h"

namespace sdog::cli {
namespace {

struct RenderArgs {
  PatternOptions pattern;
  std::string overlay = "vertex-types,crease-curves,wireframe";
  CLI::Option* overlay_opt = nullptr;
  std::string view = "side-by-side";
  bool coarse = false;
  std::string mode = "standard";
  std::string scenario = "corners";
  int iterations = 0;
  CLI::Option* iterations_opt = nullptr;
  std::string size = "1600x800";
  std::string camera;
  std::string out;
  bool transparent = false;
  std::string style = "standard";
  std::string effects = "ambient-occlusion";
};

std::string overlay_help() {
  std::string help = "comma-separated overlays (at most one of vertex-types, patches, dog-residual, edge-strain, "
                     "bending, which colour the mesh):";
  for (vis::Layer l : vis::all_layers()) help += std::string("\n  ") + vis::layer_name(l) + ": " + vis::layer_description(l);
  return help;
}

// The last state of a run of `mode` over the configuration's scenario, with the constraints at
// their final targets. Throws SolverError (naming the iteration and the cause) when the run fails.
vis::SceneState run_state(const DogModel& model, ModeKind mode, const RunConfig& config) {
  RunSetup setup(model, mode, config);
  const RunSummary summary = setup.run({});
  if (summary.failed())
    throw SolverError(std::string("the solver (") + mode_name(mode) + ") failed at " + summary.failure);
  return vis::scene_state(setup.problem(), setup.positions(), setup.mode().coarse_positions(), &setup.scenario(), 1);
}

void render(const RenderArgs& a) {
  vis::PictureOptions options;
  options.size = vis::parse_image_size(a.size);
  options.paper = a.style == "paper";
  // The paper style draws the crease curves alone unless overlays are asked for.
  options.layers = vis::parse_layers(options.paper && a.overlay_opt->count() == 0 ? "crease-curves" : a.overlay);
  options.effects = vis::parse_paper_effects(a.effects);
  options.scene.view = vis::parse_view(a.view);
  options.scene.coarse = a.coarse;
  options.transparent = a.transparent;
  if (!a.camera.empty()) options.camera = vis::load_camera(a.camera);
  const bool run = a.iterations_opt->count() > 0;
  RunConfig config;
  config.scenario = parse_scenario(a.scenario, "--scenario: ");
  config.iterations = a.iterations;
  config.hold = 0;
  const ModeKind mode = parse_mode(a.mode, "--mode: ");
  if (run) validate_run_config(config, "command line");
  // Fail on a missing display or an unusable output directory before the work.
  vis::require_display();
  const std::filesystem::path target(a.out);
  OutputSet out(target.has_parent_path() ? target.parent_path().string() : ".");

  const DogModel model = build_model(a.pattern);
  options.caption = std::filesystem::path(a.pattern.pattern).stem().string() + " " + model.fine_res.str();
  vis::SceneState state;
  if (run) {
    state = run_state(model, mode, config);
    options.caption += ", " + a.mode + ", " + std::to_string(a.iterations) + " iterations of " + a.scenario;
  } else if (std::find(options.layers.begin(), options.layers.end(), vis::Layer::Handles) != options.layers.end()) {
    const Scenario scenario = make_scenario(config, model.fine);
    state = vis::rest_scene_state(model, &scenario);
    options.caption += ", targets of " + a.scenario;
  } else {
    state = vis::rest_scene_state(model);
  }
  vis::render_picture(model, state, options, out.temporary(target.filename().string()));
  for (const auto& f : out.commit()) std::cout << "wrote " << f << "\n";
}

}  // namespace

void register_render_command(CLI::App& app, Runner& run) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Render the meshed pattern with overlays offscreen to PNG, optionally after a solver run (needs an X "
      "display: use xvfb-run on a headless machine)");
  add_pattern_options(*cmd, args->pattern);
  args->overlay_opt = cmd->add_option("--overlay", args->overlay, overlay_help())->capture_default_str();
  cmd->add_option("--view", args->view,
                  "3d: current positions seen from the front right, above; flat: the rest state seen from above; "
                  "side-by-side: fine (left) and coarse (right) meshes seen from above")
      ->capture_default_str();
  cmd->add_flag("--coarse", args->coarse, "3d and flat views: draw the coarse mesh's edges over the fine mesh");
  args->iterations_opt = cmd->add_option("--iters", args->iterations,
                                         "first run the solver for N iterations of the scenario (targets reach "
                                         "their end at iteration N), then draw the last state")
                             ->check(CLI::Range(1, 1000000));
  cmd->add_option("--mode", args->mode, "solver mode of the run (" + known_modes() + ")")
      ->capture_default_str()
      ->needs(args->iterations_opt);
  cmd->add_option("--scenario", args->scenario,
                  "scenario of the run, and whose targets the handles overlay shows without a run")
      ->check(CLI::IsMember(scenario_names()))
      ->capture_default_str();
  cmd->add_option("--size", args->size, "image size WIDTHxHEIGHT in pixels")->capture_default_str();
  cmd->add_option("--camera", args->camera,
                  "camera pose (JSON: position, focal_point, view_up, view_angle, parallel, parallel_scale, "
                  "window_center; as the studio saves it) instead of the view's default camera");
  cmd->add_option("--out", args->out, "PNG file to write")->required();
  cmd->add_flag("--transparent", args->transparent, "transparent background");
  cmd->add_option("--style", args->style,
                  "standard: the debugging view (legends, caption, dots); paper: a figure for a publication (smooth "
                  "paper-coloured surface, crease curves coloured by assignment, a light kit, antialiasing, no "
                  "legends or caption; overlays: crease-curves unless --overlay says otherwise)")
      ->check(CLI::IsMember({"standard", "paper"}))
      ->capture_default_str();
  cmd->add_option("--effects", args->effects,
                  "paper style: comma-separated render effects, ambient-occlusion and/or shadows, or none")
      ->capture_default_str();
  cmd->callback([args, &run]() { run = [args]() { render(*args); }; });
}

}  // namespace sdog::cli
