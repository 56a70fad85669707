// sdog compare: the thesis protocol for several solver modes on the same patterns and resolutions;
// a table (compare.csv), the per-iteration series (series.csv), compare.json and PNG plots (those
// only with an X display).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/compare_plots.h"
#include "app/progress.h"
#include "app/threads.h"
#include "app/versions.h"
#include "base/atomic_output.h"
#include "base/csv.h"
#include "base/errors.h"
#include "base/text_format.h"
#include "solver/config/run_config_json.h"
#include "solver/experiments/case_rounds.h"
#include "solver/experiments/tables.h"
#include "ui/vis/line_chart.h"

namespace sdog::cli {
namespace {

struct CompareArgs : CaseGridArgs {
  std::vector<std::string> modes{"all"};
  ScheduleOptions schedule;
  std::string scenario = "corners";
  std::string config;
  CLI::Option* scenario_opt = nullptr;
  int threads = 0;
  int repeat = 1;
  std::string out;
  std::string plot_size = "1600x1000";
  std::string command_line;
};

// The requested modes, `standard` first (the other rows are measured against it, so every row can
// be printed with its ratios as soon as it is done).
std::vector<ModeKind> resolve_modes(const std::vector<std::string>& requested) {
  std::vector<ModeKind> modes;
  for (const auto& m : requested) {
    const std::vector<std::string> names =
        m == "all" ? enum_names<ModeKind>() : std::vector<std::string>{m};
    for (const auto& n : names) {
      const ModeKind mode = parse_enum<ModeKind>(n, "--modes: ");
      if (std::find(modes.begin(), modes.end(), mode) == modes.end()) modes.push_back(mode);
    }
  }
  if (modes.empty())
    throw UsageError("--modes: give at least one mode (" + known_names<ModeKind>() + ") or 'all'");
  std::stable_partition(modes.begin(), modes.end(),
                        [](ModeKind m) { return m == ModeKind::kStandard; });
  return modes;
}

// Every (pattern, resolution) in order, each as its cases of every mode.
std::vector<std::vector<Case>> make_places(const CompareArgs& a,
                                           const std::vector<ModeKind>& modes) {
  std::vector<Case> places;
  if (a.thesis_grid) {
    places = thesis_grid(a.patterns_dir, modes.front());
  } else {
    if (a.patterns.empty() || a.resolutions.empty())
      throw UsageError("give --pattern and --res (or --thesis-grid)");
    for (const auto& r : a.resolutions) parse_resolution(r);
    for (const auto& p : a.patterns) {
      if (!std::filesystem::is_regular_file(p))
        throw InputError(p + ": no such crease pattern file");
      for (const auto& r : a.resolutions) places.push_back({p, r});
    }
  }
  std::vector<std::vector<Case>> cases(places.size());
  for (size_t i = 0; i < places.size(); ++i)
    for (ModeKind m : modes) cases[i].push_back({places[i].pattern, places[i].res, m});
  return cases;
}

// The table on stdout: fixed column widths so that rows printed one by one line up.
void print_fields(const std::vector<std::string>& fields) {
  static const std::map<std::string, int> min_width = {{"pattern", 18}, {"mode", 11}};
  const auto columns = compare_columns();
  std::string line;
  for (size_t i = 0; i < fields.size(); ++i) {
    const auto it = min_width.find(columns[i]);
    const size_t width =
        std::max<size_t>(columns[i].size(), it == min_width.end() ? 8 : it->second);
    std::string f = fields[i];
    if (i + 1 < fields.size()) f.resize(std::max(width, f.size()), ' ');
    line += f + (i + 1 < fields.size() ? " " : "");
  }
  std::cout << line << "\n" << std::flush;
}

nlohmann::json row_json(const CaseResult& r) {
  auto optional = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  nlohmann::json j = {{"pattern", r.pattern},
                      {"res", r.res},
                      {"mode", enum_name(r.mode)},
                      {"status", enum_name(r.status)},
                      {"note", r.note}};
  if (r.status == CaseStatus::kSkipped) return j;
  j.update({{"vertices", r.vertices},
            {"dof", r.dof},
            {"iterations", r.iterations},
            {"final_objective", r.final_objective},
            {"objective_ratio", optional(r.objective_ratio)},
            {"median_ms", r.median_ms},
            {"speedup", optional(r.speedup)},
            {"total_s", r.total_s},
            {"total_speedup", optional(r.total_speedup)},
            {"round_ms", r.round_ms},
            {"speedup_paired", optional(r.speedup_paired)},
            {"dog_max", r.dog_max},
            {"dog_max_run", r.dog_max_run},
            {"stitch_gap_max", r.stitch_gap_max},
            {"folded", r.folded}});
  return j;
}

RunConfig compare_config(const CompareArgs& a) {
  RunConfig config;
  apply_preset_option(a.preset, a.thesis_grid, config);
  if (!a.config.empty()) read_run_config(a.config, config);
  if (a.scenario_opt->count() || a.config.empty())
    config.scenario = parse_enum<ScenarioKind>(a.scenario, "--scenario: ");
  if (a.schedule.iterations_opt->count() || a.config.empty())
    config.iterations = a.schedule.iterations;
  if (a.schedule.hold_opt->count() || a.config.empty()) config.hold = a.schedule.hold;
  if (!config.switches.empty())
    throw UsageError(
        a.config + ": $.switches: sdog compare runs every mode on its own (use sdog run --switch)");
  validate_run_config(config,
                      a.config.empty() ? "command line" : a.config + " with the command line",
                      a.config.empty() ? ErrorKind::kUsage : ErrorKind::kInput);
  return config;
}

// Runs the modes of one pattern and resolution in rounds (run_rounds), one progress bar per run,
// and reports each finished case on stderr and its row on stdout.
std::vector<CaseResult> compare_place(const CompareArgs& a, const std::vector<Case>& place,
                                      const RunConfig& config, size_t first_case, size_t case_count,
                                      std::chrono::steady_clock::time_point start) {
  const auto place_start = std::chrono::steady_clock::now();
  std::unique_ptr<ProgressBar> progress;
  RoundsOptions options;
  options.repeat = a.repeat;
  options.observers = [&](const Case& c, int round) -> std::vector<RunObserver*> {
    if (progress) progress->finish();
    progress = std::make_unique<ProgressBar>(config.iterations + config.hold, true);
    if (a.repeat > 1)
      std::cerr << "sdog compare: " << std::filesystem::path(c.pattern).stem().string() << " "
                << c.res << ": round " << round + 1 << "/" << a.repeat << ": " << enum_name(c.mode)
                << "\n"
                << std::flush;
    return {progress.get()};
  };
  std::vector<CaseResult> done = run_rounds(place, config, options);
  if (progress) progress->finish();
  for (size_t i = 0; i < done.size(); ++i) {
    const CaseResult& r = done[i];
    std::cerr << "sdog compare: case " << first_case + i + 1 << "/" << case_count << ": "
              << r.pattern << " " << r.res << " " << enum_name(r.mode) << ": "
              << enum_name(r.status)
              << (r.note.empty() ? ""
                                 : ": " + r.note + (r.completed() ? "" : "; recorded, going on"))
              << "\n";
    print_fields(compare_fields(r));
  }
  const std::string cases = done.size() == 1
                                ? "case " + std::to_string(first_case + 1)
                                : "cases " + std::to_string(first_case + 1) + " to " +
                                      std::to_string(first_case + done.size()) + " side by side";
  std::cerr << "sdog compare: " << cases << " in " << format_number(seconds_since(place_start))
            << " s (elapsed " << format_number(seconds_since(start)) << " s)\n"
            << std::flush;
  return done;
}

nlohmann::json compare_json(const CompareArgs& a, const std::vector<ModeKind>& modes,
                            const RunConfig& config, const std::vector<CaseResult>& rows) {
  nlohmann::json json_rows = nlohmann::json::array();
  for (const auto& r : rows) json_rows.push_back(row_json(r));
  std::vector<std::string> mode_list;
  for (ModeKind m : modes) mode_list.push_back(enum_name(m));
  return {{"command_line", a.command_line},
          {"patterns", a.thesis_grid ? std::vector<std::string>{a.patterns_dir} : a.patterns},
          {"thesis_grid", a.thesis_grid},
          {"resolutions", a.resolutions},
          {"modes", mode_list},
          {"repeat", a.repeat},
          {"threads", a.threads},
          {"plot_size", a.plot_size},
          {"config", to_json(config)},
          {"software", software_versions()},
          {"columns", compare_columns()},
          {"table", json_rows}};
}

void compare(const CompareArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  // Usage errors first (exit 2), then what cannot be written (exit 1), then the work.
  const std::vector<ModeKind> modes = resolve_modes(a.modes);
  parse_enum<ScenarioKind>(a.scenario, "--scenario: ");
  const vis::ImageSize plot_size = vis::parse_image_size(a.plot_size);
  const RunConfig config = compare_config(a);
  const std::vector<std::vector<Case>> places = make_places(a, modes);
  const size_t case_count = places.size() * modes.size();
  OutputSet out(a.out);
  // The tables need no display; without one the plots are left out, which is said once.
  const std::string no_display = vis::display_unavailable();
  if (!no_display.empty())
    std::cerr << "sdog compare: " << no_display
              << ": the plots are skipped (the tables are written); to draw them, "
              << "run the command with an X display or under `xvfb-run -a`\n";
  set_thread_count(a.threads);

  std::vector<CaseResult> rows;
  print_fields(compare_columns());
  for (const auto& place : places) {
    const std::vector<CaseResult> done =
        compare_place(a, place, config, rows.size(), case_count, start);
    rows.insert(rows.end(), done.begin(), done.end());
  }
  std::string table = csv_line(compare_columns()), series = csv_line(series_columns());
  for (const auto& r : rows) {
    table += csv_line(compare_fields(r));
    series += series_rows(r);
  }
  out.write_text("compare.csv", table);
  out.write_text("series.csv", series);
  out.write_text("compare.json", compare_json(a, modes, config, rows).dump(2) + "\n");
  std::vector<std::string> plots;
  if (no_display.empty())
    for (const auto& [name, chart] : comparison_charts(rows)) {
      vis::render_line_chart(chart, plot_size, out.temporary(name));
      plots.push_back(name);
    }
  out.commit();
  const auto failed =
      std::count_if(rows.begin(), rows.end(), [](const CaseResult& r) { return !r.completed(); });
  if (failed > 0)
    std::cerr << "sdog compare: " << failed << " of " << rows.size()
              << " runs did not complete (status column of compare.csv)\n";
  std::cout << "sdog compare: " << rows.size() << (rows.size() == 1 ? " case" : " cases")
            << (a.repeat > 1 ? " (" + std::to_string(a.repeat) + " rounds)" : std::string())
            << " in " << format_number(seconds_since(start)) << " s; wrote " << a.out
            << "/{compare.csv, series.csv, compare.json"
            << (plots.empty() ? "" : ", " + join(plots, ", ")) << "}\n";
}

}  // namespace

void register_compare_command(CLI::App& app, Runner& runner, const std::string& command_line) {
  auto a = std::make_shared<CompareArgs>();
  a->command_line = command_line;
  CLI::App* cmd = app.add_subcommand("compare",
                                     "Run the thesis protocol with several solver modes and "
                                     "compare them: compare.csv (final objective and "
                                     "its ratio to standard, median ms per iteration and the "
                                     "speedup, the whole run's time and its "
                                     "speedup, DOG residuals, stitching gap), "
                                     "series.csv, compare.json and PNG plots (the plots need an X "
                                     "display: without one they are skipped; use "
                                     "xvfb-run on a headless machine)");
  cmd->add_option("--pattern", a->patterns, "crease pattern(s) (SVG or FOLD)");
  cmd->add_option("--res", a->resolutions,
                  "resolution(s) XxY (odd for modes that need the coarse mesh)");
  cmd->add_option("--modes", a->modes,
                  "'all' or solver modes, comma separated (" + known_names<ModeKind>() + ")")
      ->delimiter(',')
      ->capture_default_str();
  add_case_grid_options(*cmd, *a);
  add_schedule_options(*cmd, a->schedule);
  a->scenario_opt = cmd->add_option("--scenario", a->scenario,
                                    "scenario of every run (" + known_names<ScenarioKind>() + ")")
                        ->capture_default_str();
  cmd->add_option(
      "--config", a->config,
      "JSON file of weights, solver and mode options (as for sdog run; no switches) for every run; "
      "--iters, --hold and --scenario win");
  cmd->add_option("--threads", a->threads, "threads for parallel patch solves (0: one per core)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_option(
         "--repeat", a->repeat,
         "runs per case, in rounds over the modes (median_ms: the median of their medians; "
         "speedup_paired: the median of the rounds' ratios)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--out", a->out,
                  "directory for compare.csv, series.csv, compare.json and the plots")
      ->required();
  cmd->add_option("--plot-size", a->plot_size, "size of the PNG plots WIDTHxHEIGHT in pixels")
      ->capture_default_str();
  cmd->callback([a, &runner]() { runner = [a]() { compare(*a); }; });
}

}  // namespace sdog::cli
