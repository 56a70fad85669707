// sdog render: headless pictures of a meshed pattern.
#include <iostream>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "geometry/atomic_output.h"
#include "ui/vis/vertex_type_picture.h"

namespace sdog::cli {
namespace {

struct RenderArgs {
  PatternOptions pattern;
  std::string overlay = "vertex-types";
  std::string size = "1600x800";
  std::string out;
  bool transparent = false;
};

}  // namespace

void register_render_command(CLI::App& app, Runner& run) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Render a picture of the meshed pattern offscreen to PNG (needs an X display: "
      "use xvfb-run on a headless machine)");
  add_pattern_options(*cmd, args->pattern);
  cmd->add_option("--overlay", args->overlay,
                  "what to show: vertex-types (fine and coarse meshes, vertices coloured link / I "
                  "/ X / coarse-only, crease points pink)")
      ->capture_default_str()
      ->check(CLI::IsMember({"vertex-types"}));
  cmd->add_option("--size", args->size, "image size WIDTHxHEIGHT in pixels")->capture_default_str();
  cmd->add_option("--out", args->out, "PNG file to write")->required();
  cmd->add_flag("--transparent", args->transparent, "transparent background");
  cmd->callback([args, &run]() {
    run = [args]() {
      const vis::ImageSize size = vis::parse_image_size(args->size);
      const DogModel model = build_model(args->pattern);
      const std::filesystem::path target(args->out);
      OutputSet out(target.has_parent_path() ? target.parent_path().string() : ".");
      vis::render_vertex_types(model, out.temporary(target.filename().string()), size,
                               args->transparent);
      for (const auto& f : out.commit()) std::cout << "wrote " << f << "\n";
    };
  });
}

}  // namespace sdog::cli
