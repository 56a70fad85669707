#include "app/cli_common.h"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "app/commands.h"
#include "app/versions.h"

#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/input/pattern_file.h"

namespace sdog::cli {

void add_preset_option(CLI::App& cmd, std::string& preset) {
  cmd.add_option(
         "--preset", preset,
         "solver settings to start from, before --config and the other options: default (exact "
         "stitching) or thesis (the thesis's solver, for its numbers)")
      ->check(CLI::IsMember(enum_names<Preset>()));
}

void apply_preset_option(const std::string& preset, bool thesis_grid, RunConfig& config) {
  const std::string name = !preset.empty() ? preset : thesis_grid ? "thesis" : "";
  if (!name.empty()) apply_preset(config.preset = parse_enum<Preset>(name, "--preset: "), config);
}

void add_pattern_options(CLI::App& cmd, PatternOptions& o, bool required) {
  cmd.add_option("PATTERN", o.pattern,
                 "crease pattern: an SVG drawing (black strokes = sheet boundary, other colours = "
                 "creases) or a FOLD file (.fold)")
      ->required(required);
  cmd.add_option("--res", o.res,
                 "grid lines XxY such as 31x21 (odd numbers when a coarse mesh is built), or "
                 "'auto': 41 along the longer side")
      ->capture_default_str();
  cmd.add_option("--flatness", o.flatness,
                 "largest chord deviation when flattening curves, as a fraction of the sheet size")
      ->capture_default_str()
      ->check(CLI::Range(1e-9, 1e-2));
  auto given = [&o](const std::string&) { o.tolerances_given = true; };
  cmd.add_option("--merge-tol", o.merge_fraction,
                 "crease ends and crossings closer than this fraction of the sheet size merge "
                 "(unset: a drawing too dense for the default is cleaned with a tenth, or a "
                 "hundredth, of both tolerances)")
      ->capture_default_str()
      ->each(given);
  cmd.add_option("--snap-tol", o.snap_fraction,
                 "free crease ends snap to the boundary or a crease within this fraction of the "
                 "sheet size; nearby junction coordinates align")
      ->capture_default_str()
      ->each(given);
  cmd.add_flag("--fine-only", o.fine_only,
               "build only the fine mesh (allows even resolutions; no coarse mesh, no map)");
}

DogModel build_model(const PatternOptions& o, bool warn) {
  MeshOptions mesh_options;
  mesh_options.cleaning.merge_fraction = o.merge_fraction;
  mesh_options.cleaning.snap_fraction = o.snap_fraction;
  mesh_options.cleaning.adapt = !o.tolerances_given;
  mesh_options.build_coarse = !o.fine_only;
  mesh_options.coarse = o.coarse;
  if (const std::string msg = mesh_options.cleaning.validate(); !msg.empty()) throw UsageError(msg);
  if (o.res != "auto") check_resolution(parse_resolution(o.res), mesh_options.build_coarse);
  SvgReadOptions svg;
  svg.flatness = o.flatness;
  const CreasePattern pattern = read_crease_pattern(o.pattern, svg);
  const Resolution res =
      resolve_resolution(o.res, pattern.sheet.bbox.width(), pattern.sheet.bbox.height());
  try {
    DogModel model = build_dog_model(pattern, res, mesh_options);
    if (warn) print_warnings(model);
    return model;
  } catch (const UsageError& e) {
    // The resolution is too low for the pattern: say which one is enough.
    const std::optional<Resolution> enough = lowest_meshing_resolution(pattern, res, mesh_options);
    throw UsageError(
        std::string(e.what()) +
        (enough ? "; it meshes at " + enough->str() + ", the lowest resolution found by trying"
                : "; it meshes at no resolution up to " + format_number(kResolutionReach) +
                      " times this one either"));
  }
}

void print_warnings(const DogModel& model) {
  for (const auto& w : model_warnings(model)) std::cerr << "warning: " << w << "\n";
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string command_line_text(int argc, char** argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.empty() || arg.find_first_of(" \t'\"\\$") != std::string::npos) {
      std::string quoted = "'";
      for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
      arg = quoted + "'";
    }
    line += (i ? " " : "") + arg;
  }
  return line;
}

void register_sdog_commands(CLI::App& app, Runner& run, const std::string& command_line) {
  app.name("sdog");
  app.description(
      "Scalable DOGs: crease patterns (SVG or FOLD) to discrete orthogonal geodesic nets (DOGs), "
      "their coarse twins and the map between them.\nRun `sdog COMMAND --help` for a command's "
      "options.");
  app.require_subcommand(1);
  app.set_version_flag("--version", version_line("sdog"), "Print the version and exit");
  register_mesh_command(app, run);
  register_render_command(app, run);
  register_run_command(app, run);
  register_bench_command(app, run);
  register_compare_command(app, run, command_line);
}

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  const std::string usage = " (run `" + app.get_name() + " --help` for usage)";
  std::vector<std::string> names;
  for (const CLI::App* c : app.get_subcommands({})) names.push_back(c->get_name());
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  if (argc < 2) throw UsageError("no command given; the commands are " + list + usage);
  if (argv[1][0] != '-' && std::find(names.begin(), names.end(), argv[1]) == names.end())
    throw UsageError(std::string("unknown command '") + argv[1] + "'; the commands are " + list +
                     usage);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what() + usage);
  }
  return std::nullopt;
}

void add_schedule_options(CLI::App& cmd, ScheduleOptions& o) {
  o.iterations_opt =
      cmd.add_option("--iters", o.iterations, "iterations over which the targets move")
          ->check(CLI::Range(0, 1000000))
          ->capture_default_str();
  o.hold_opt = cmd.add_option("--hold", o.hold, "iterations with the final targets")
                   ->check(CLI::Range(0, 1000000))
                   ->capture_default_str();
}

void add_case_grid_options(CLI::App& cmd, CaseGridArgs& a) {
  cmd.add_flag("--thesis-grid", a.thesis_grid,
               "the 16 cases of the thesis (4 patterns x 4 resolutions), with the thesis preset "
               "unless --preset says otherwise");
  add_preset_option(cmd, a.preset);
  cmd.add_option("--patterns-dir,--patterns", a.patterns_dir,
                 "folder of the thesis patterns for --thesis-grid")
      ->capture_default_str();
}

}  // namespace sdog::cli
