// sdog compare: the thesis protocol for several solver modes on the same patterns and resolutions;
// a table (compare.csv), the per-iteration series (series.csv), compare.json and PNG plots.
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
#include "app/progress.h"
#include "app/threads.h"
#include "app/versions.h"
#include "base/atomic_output.h"
#include "base/errors.h"
#include "base/text_format.h"
#include "solver/experiments/comparison.h"
#include "solver/modes/mode_factory.h"
#include "ui/vis/line_chart.h"

namespace sdog::cli {
namespace {

struct CompareArgs {
  std::vector<std::string> patterns;
  std::vector<std::string> resolutions;
  std::vector<std::string> modes{"all"};
  bool thesis_grid = false;
  std::string patterns_dir = "../shared/reference/patterns";
  int iterations = 250;
  int hold = 50;
  std::string scenario = "corners";
  std::string config;
  CLI::Option *scenario_opt = nullptr, *iterations_opt = nullptr, *hold_opt = nullptr;
  int threads = 0;
  int repeat = 1;
  std::string out;
  std::string plot_size = "1600x1000";
  std::string command_line;
};

// The requested modes, `standard` first (the other rows are measured against it, so every row can
// be printed with its ratios as soon as it is done).
std::vector<std::string> resolve_modes(const std::vector<std::string>& requested) {
  std::vector<std::string> modes;
  for (const auto& m : requested) {
    const std::vector<std::string> names = m == "all" ? mode_names() : std::vector<std::string>{m};
    for (const auto& n : names) {
      check_mode_name(n, "--modes: ");
      if (std::find(modes.begin(), modes.end(), n) == modes.end()) modes.push_back(n);
    }
  }
  if (modes.empty()) throw UsageError("--modes: give at least one mode (" + known_modes() + ") or 'all'");
  std::stable_partition(modes.begin(), modes.end(), [](const std::string& m) { return m == "standard"; });
  return modes;
}

// Every (pattern, resolution) in order, each as its cases of every mode.
std::vector<std::vector<BenchCase>> make_places(const CompareArgs& a, const std::vector<std::string>& modes) {
  std::vector<BenchCase> places;
  if (a.thesis_grid) {
    places = thesis_grid(a.patterns_dir, modes.front());
  } else {
    if (a.patterns.empty() || a.resolutions.empty()) throw UsageError("give --pattern and --res (or --thesis-grid)");
    for (const auto& r : a.resolutions) parse_resolution(r);
    for (const auto& p : a.patterns) {
      if (!std::filesystem::is_regular_file(p)) throw InputError(p + ": no such crease pattern file");
      for (const auto& r : a.resolutions) places.push_back({p, r, ""});
    }
  }
  std::vector<std::vector<BenchCase>> cases(places.size());
  for (size_t i = 0; i < places.size(); ++i)
    for (const auto& m : modes) cases[i].push_back({places[i].pattern, places[i].res, m});
  return cases;
}

// The table on stdout: fixed column widths so that rows printed one by one line up.
void print_fields(const std::vector<std::string>& fields) {
  static const std::map<std::string, int> min_width = {{"pattern", 18}, {"mode", 11}};
  const auto columns = compare_columns();
  std::string line;
  for (size_t i = 0; i < fields.size(); ++i) {
    const auto it = min_width.find(columns[i]);
    const size_t width = std::max<size_t>(columns[i].size(), it == min_width.end() ? 8 : it->second);
    std::string f = fields[i];
    if (i + 1 < fields.size()) f.resize(std::max(width, f.size()), ' ');
    line += f + (i + 1 < fields.size() ? " " : "");
  }
  std::cout << line << "\n" << std::flush;
}

nlohmann::json row_json(const CompareRow& r) {
  auto optional = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  nlohmann::json j = {{"pattern", r.pattern}, {"res", r.res}, {"mode", r.mode}, {"status", to_string(r.status)},
                      {"note", r.note}};
  if (r.status == CompareStatus::Skipped) return j;
  j.update({{"vertices", r.vertices}, {"dof", r.dof}, {"iterations", r.iterations},
            {"final_objective", r.final_objective}, {"objective_ratio", optional(r.objective_ratio)},
            {"median_ms", r.median_ms}, {"speedup", optional(r.speedup)}, {"total_s", r.total_s},
            {"total_speedup", optional(r.total_speedup)}, {"round_ms", r.round_ms},
            {"speedup_paired", optional(r.speedup_paired)}, {"dog_max", r.dog_max},
            {"dog_max_run", r.dog_max_run}, {"stitch_gap_max", r.stitch_gap_max}, {"folded", r.folded}});
  return j;
}

// A fixed colour per mode name, so that every plot of a comparison (and of later ones) agrees: the
// palette's colours in the order of the modes, except that the sixth mode (coarse) takes the fifth
// colour (orange) and the fifth mode the sixth (sky blue), which is hard to tell from the standard
// mode's blue, and coarse is usually drawn beside it.
vis::Rgb mode_color(const std::string& mode) {
  const auto names = mode_names();
  const int index = static_cast<int>(std::find(names.begin(), names.end(), mode) - names.begin());
  const int kOrange = 4, kSkyBlue = 5;
  return vis::series_color(index == kSkyBlue ? kOrange : index == kOrange ? kSkyBlue : index);
}

vis::ChartSeries mode_series(const CompareRow& r) {
  vis::ChartSeries s;
  s.name = r.mode + (r.completed() ? "" : " (" + std::string(to_string(r.status)) + ")");
  s.color = mode_color(r.mode);
  return s;
}

// Plots of one pattern and resolution: objective and time per iteration against iteration.
std::vector<std::pair<std::string, vis::LineChart>> case_charts(const std::vector<const CompareRow*>& rows) {
  const std::string place = rows.front()->pattern + " " + rows.front()->res;
  vis::LineChart objective = vis::titled_chart(place + ": objective", "iteration", "objective (weighted, fine mesh)");
  vis::LineChart time = vis::titled_chart(place + ": time per iteration", "iteration", "time per iteration (ms)");
  // The modes' objectives differ by orders of magnitude (thesis Fig. 6.2), and the first and last
  // iterations (symbolic analysis, final polish) take many times longer than the others.
  objective.log_y = time.log_y = true;
  for (const CompareRow* r : rows) {
    if (r->series.empty()) continue;
    vis::ChartSeries o = mode_series(*r), t = mode_series(*r);
    for (const auto& p : r->series) {
      o.x.push_back(p.iteration);
      o.y.push_back(p.objective);
      t.x.push_back(p.iteration);
      t.y.push_back(p.ms);
    }
    objective.series.push_back(o);
    time.series.push_back(t);
  }
  if (objective.series.empty()) return {};
  const std::string suffix = rows.front()->pattern + "_" + rows.front()->res + ".png";
  return {{"objective_" + suffix, objective}, {"time_" + suffix, time}};
}

// ms per iteration per DoF against the vertex count, one line per mode, for a pattern run at more
// than one resolution (completed runs only).
std::optional<vis::LineChart> scaling_chart(const std::string& pattern, const std::vector<CompareRow>& rows) {
  vis::LineChart chart =
      vis::titled_chart(pattern + ": time per iteration per DoF", "fine vertices", "time per iteration per DoF (ms)");
  std::set<std::string> resolutions;
  std::map<std::string, vis::ChartSeries> by_mode;
  for (const auto& r : rows) {
    if (r.pattern != pattern || !r.completed()) continue;
    resolutions.insert(r.res);
    auto [it, fresh] = by_mode.try_emplace(r.mode, mode_series(r));
    it->second.x.push_back(r.vertices);
    it->second.y.push_back(r.ms_per_dof());
  }
  if (resolutions.size() < 2) return std::nullopt;
  for (const auto& name : mode_names()) {
    const auto it = by_mode.find(name);
    if (it == by_mode.end()) continue;
    vis::ChartSeries s = it->second;
    std::vector<size_t> order(s.x.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return s.x[i] < s.x[j]; });
    vis::ChartSeries sorted{s.name, {}, {}, s.color};
    for (size_t i : order) {
      sorted.x.push_back(s.x[i]);
      sorted.y.push_back(s.y[i]);
    }
    chart.series.push_back(sorted);
  }
  return chart;
}

// Every plot of the comparison, by file name.
std::vector<std::pair<std::string, vis::LineChart>> all_charts(const std::vector<CompareRow>& rows) {
  std::vector<std::pair<std::string, vis::LineChart>> charts;
  std::vector<std::string> patterns;
  for (size_t i = 0; i < rows.size();) {
    std::vector<const CompareRow*> place;
    size_t j = i;
    for (; j < rows.size() && rows[j].pattern == rows[i].pattern && rows[j].res == rows[i].res; ++j)
      place.push_back(&rows[j]);
    for (auto& c : case_charts(place)) charts.push_back(std::move(c));
    if (std::find(patterns.begin(), patterns.end(), rows[i].pattern) == patterns.end())
      patterns.push_back(rows[i].pattern);
    i = j;
  }
  for (const auto& p : patterns)
    if (auto chart = scaling_chart(p, rows)) charts.push_back({"ms_per_dof_" + p + ".png", *chart});
  return charts;
}

void compare(const CompareArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  // Usage errors first (exit 2), then what cannot be written or drawn (exit 1), then the work.
  const std::vector<std::string> modes = resolve_modes(a.modes);
  check_scenario_name(a.scenario, "--scenario: ");
  const vis::ImageSize plot_size = vis::parse_image_size(a.plot_size);
  RunConfig config;
  if (!a.config.empty()) read_run_config(a.config, config);
  if (a.scenario_opt->count() || a.config.empty()) config.scenario = a.scenario;
  if (a.iterations_opt->count() || a.config.empty()) config.iterations = a.iterations;
  if (a.hold_opt->count() || a.config.empty()) config.hold = a.hold;
  if (!config.switches.empty())
    throw UsageError(a.config + ": $.switches: sdog compare runs every mode on its own (use sdog run --switch)");
  validate_run_config(config, a.config.empty() ? "command line" : a.config + " with the command line");
  const std::vector<std::vector<BenchCase>> places = make_places(a, modes);
  const size_t case_count = places.size() * modes.size();
  OutputSet out(a.out);
  vis::require_display();
  set_thread_count(a.threads);

  std::vector<CompareRow> rows;
  print_fields(compare_columns());
  // The modes of a pattern and resolution run in rounds (run_compare_rounds), one progress bar
  // per run.
  for (const auto& place : places) {
    const size_t first = rows.size();
    const auto place_start = std::chrono::steady_clock::now();
    std::unique_ptr<ProgressBar> progress;
    auto observers = [&](const BenchCase& c, int round) -> std::vector<RunObserver*> {
      if (progress) progress->finish();
      progress = std::make_unique<ProgressBar>(config.iterations + config.hold, true);
      if (a.repeat > 1)
        std::cerr << "sdog compare: " << std::filesystem::path(c.pattern).stem().string() << " " << c.res
                  << ": round " << round + 1 << "/" << a.repeat << ": " << c.mode << "\n"
                  << std::flush;
      return {progress.get()};
    };
    const std::vector<CompareRow> done = run_compare_rounds(place, config, a.repeat, observers);
    if (progress) progress->finish();
    rows.insert(rows.end(), done.begin(), done.end());
    relate_to_standard(rows);
    for (size_t i = first; i < rows.size(); ++i) {
      const CompareRow& r = rows[i];
      std::cerr << "sdog compare: case " << i + 1 << "/" << case_count << ": " << r.pattern << " " << r.res << " "
                << r.mode << ": " << to_string(r.status) << " (" << place.size() << " cases in "
                << format_number(seconds_since(place_start)) << " s, elapsed " << format_number(seconds_since(start))
                << " s)" << (r.note.empty() ? "" : ": " + r.note + (r.completed() ? "" : "; recorded, going on"))
                << "\n"
                << std::flush;
      print_fields(compare_fields(r));
    }
  }

  std::string table = csv_line(compare_columns()), series = series_csv_header();
  nlohmann::json json_rows = nlohmann::json::array();
  for (const auto& r : rows) {
    table += csv_line(compare_fields(r));
    series += series_csv_rows(r);
    json_rows.push_back(row_json(r));
  }
  out.write_text("compare.csv", table);
  out.write_text("series.csv", series);
  const nlohmann::json j = {
      {"command_line", a.command_line},
      {"patterns", a.thesis_grid ? std::vector<std::string>{a.patterns_dir} : a.patterns},
      {"thesis_grid", a.thesis_grid},
      {"resolutions", a.resolutions},
      {"modes", modes},
      {"repeat", a.repeat},
      {"threads", a.threads},
      {"plot_size", a.plot_size},
      {"config", to_json(config)},
      {"software", software_versions()},
      {"columns", compare_columns()},
      {"table", json_rows}};
  out.write_text("compare.json", j.dump(2) + "\n");
  std::vector<std::string> plots;
  for (const auto& [name, chart] : all_charts(rows)) {
    vis::render_line_chart(chart, plot_size, out.temporary(name));
    plots.push_back(name);
  }
  out.commit();
  const auto failed = std::count_if(rows.begin(), rows.end(), [](const CompareRow& r) { return !r.completed(); });
  if (failed > 0)
    std::cerr << "sdog compare: " << failed << " of " << rows.size()
              << " runs did not complete (status column of compare.csv)\n";
  std::cout << "sdog compare: " << rows.size() << " cases"
            << (a.repeat > 1 ? " (" + std::to_string(a.repeat) + " rounds)" : std::string()) << " in "
            << format_number(seconds_since(start)) << " s; wrote "
            << a.out << "/{compare.csv, series.csv, compare.json" << (plots.empty() ? "" : ", " + join(plots, ", "))
            << "}\n";
}

}  // namespace

void register_compare_command(CLI::App& app, Runner& runner, const std::string& command_line) {
  auto a = std::make_shared<CompareArgs>();
  a->command_line = command_line;
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Run the thesis protocol with several solver modes and compare them: compare.csv (final objective and "
      "its ratio to standard, median ms per iteration and the speedup, the whole run's time and its "
      "speedup, DOG residuals, stitching gap), "
      "series.csv, compare.json and PNG plots (needs an X display: use xvfb-run on a headless machine)");
  cmd->add_option("--pattern", a->patterns, "crease pattern(s) (SVG)");
  cmd->add_option("--res", a->resolutions, "resolution(s) XxY (odd for modes that need the coarse mesh)");
  cmd->add_option("--modes", a->modes, "'all' or solver modes, comma separated (" + known_modes() + ")")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_flag("--thesis-grid", a->thesis_grid, "the 16 cases of the thesis (4 patterns x 4 resolutions)");
  cmd->add_option("--patterns-dir,--patterns", a->patterns_dir, "folder of the thesis patterns for --thesis-grid")
      ->capture_default_str();
  a->iterations_opt = cmd->add_option("--iters", a->iterations, "iterations over which the targets move")
                          ->check(CLI::Range(0, 1000000))
                          ->capture_default_str();
  a->hold_opt = cmd->add_option("--hold", a->hold, "iterations with the final targets")
                    ->check(CLI::Range(0, 1000000))
                    ->capture_default_str();
  a->scenario_opt =
      cmd->add_option("--scenario", a->scenario, "scenario of every run (" + join(scenario_names(), ", ") + ")")
          ->capture_default_str();
  cmd->add_option("--config", a->config,
                  "JSON file of weights, solver and mode options (as for sdog run; no switches) for every run; "
                  "--iters, --hold and --scenario win");
  cmd->add_option("--threads", a->threads, "threads for parallel patch solves (0: one per core)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_option("--repeat", a->repeat,
                  "runs per case, in rounds over the modes (median_ms: the median of their medians; "
                  "speedup_paired: the median of the rounds' ratios)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--out", a->out, "directory for compare.csv, series.csv, compare.json and the plots")->required();
  cmd->add_option("--plot-size", a->plot_size, "size of the PNG plots WIDTHxHEIGHT in pixels")->capture_default_str();
  cmd->callback([a, &runner]() { runner = [a]() { compare(*a); }; });
}

}  // namespace sdog::cli
