// sdog bench: speed of the solver modes on the thesis protocol, the pace of the corners drag, and
// the fold of crease patterns, as tables and CSV.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/threads.h"
#include "base/atomic_output.h"
#include "base/csv.h"
#include "base/errors.h"
#include "solver/config/run_config_json.h"
#include "solver/experiments/case_rounds.h"
#include "solver/experiments/pace.h"
#include "solver/experiments/tables.h"
#include "solver/experiments/trim_cost.h"

namespace sdog::cli {
namespace {

// "  RES MODE: round K/N, iteration I/T" on stderr every 10 iterations.
class CaseProgress : public RunObserver {
 public:
  CaseProgress(const Case& c, int round, int rounds, int total)
      : c_(c), round_(round), rounds_(rounds), total_(total) {}
  void on_iteration(const IterationReport& r, const Dofs&) override {
    if (r.iteration % 10 == 0 || r.iteration == total_)
      std::fprintf(stderr, "\r  %s %s: round %d/%d, iteration %d/%d   ", c_.res.c_str(),
                   enum_name(c_.mode), round_ + 1, rounds_, r.iteration, total_);
  }

 private:
  Case c_;
  int round_, rounds_, total_;
};

struct BenchArgs : CaseGridArgs {
  std::vector<std::string> modes{"standard"};
  int iterations = 250;
  int repeat = 3;
  int threads = 0;
  std::string csv;
  std::string config;
  bool pace = false;
  bool fold = false;
  bool trim = false;
  std::vector<int> ks{250, 50, 10, 1};
  CLI::Option* ks_opt = nullptr;
  CLI::Option* repeat_opt = nullptr;
  std::vector<double> angles{60};
  int max_hold = 200;
};

void print_row(const CaseResult& r) {
  char speedup[32] = "";
  if (r.speedup) std::snprintf(speedup, sizeof speedup, "%.2f", *r.speedup);
  const Work& w = r.window_work;
  std::printf("%-18s %-6s %-9s %6d %6d %9.2f %9.5f %6.2f %9.2f %7.2f %10.4g %9.2g %7s\n",
              r.pattern.c_str(), r.res.c_str(), enum_name(r.mode), r.vertices, r.dof, r.median_ms,
              r.ms_per_dof(), r.per_window_iteration(w.steps), r.per_window_iteration(w.factor_ms),
              r.per_window_iteration(w.factorizations), r.final_objective, r.dog_max, speedup);
  std::fflush(stdout);
}

// Per pattern and resolution (a place) the case of every mode; the modes of a place run in rounds.
std::vector<std::vector<Case>> bench_places(const BenchArgs& a,
                                            const std::vector<ModeKind>& modes) {
  std::vector<Case> places;
  if (a.thesis_grid) {
    places = thesis_grid(a.patterns_dir);
  } else {
    if (a.patterns.empty() || a.resolutions.empty())
      throw UsageError("give --pattern and --res (or --thesis-grid)");
    for (const auto& p : a.patterns)
      for (const auto& r : a.resolutions) places.push_back({p, r});
  }
  std::vector<std::vector<Case>> cases;
  for (const Case& place : places) {
    cases.emplace_back();
    for (ModeKind m : modes) cases.back().push_back({place.pattern, place.res, m});
  }
  return cases;
}

std::string fixed(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

std::string general(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// The table as CSV, when --csv asked for it.
void write_csv(std::unique_ptr<OutputSet>& out, const std::string& csv_name,
               const std::string& csv) {
  if (!out) return;
  out->write_text(csv_name, csv);
  for (const auto& f : out->commit()) std::cout << "wrote " << f << "\n";
}

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

// The configuration of --preset and --config (the pace and fold benchmarks).
RunConfig paced_config(const BenchArgs& a) {
  RunConfig config;
  apply_preset_option(a.preset, false, config);
  if (!a.config.empty()) {
    read_run_config(a.config, config);
    validate_run_config(config, a.config);
  }
  return config;
}

// Every pattern at every resolution of the pace and fold benchmarks, meshed (its warnings
// printed).
void for_each_case(const BenchArgs& a,
                   const std::function<void(const std::string& pattern, const std::string& res,
                                            const DogModel& model)>& each) {
  for (const auto& pattern : a.patterns)
    for (const auto& res : a.resolutions) {
      const DogModel model = build_case_model({pattern, res, ModeKind::kStandard});
      print_warnings(model);
      each(pattern, res, model);
    }
}

// Per pattern and resolution, the corners drag over each K, then held until converged.
void bench_pace(const BenchArgs& a, std::unique_ptr<OutputSet>& out, const std::string& csv_name) {
  if (a.patterns.empty() || a.resolutions.empty())
    throw UsageError("--pace: give --pattern and --res");
  const RunConfig config = paced_config(a);
  const std::vector<std::string> header{"pattern",         "res",     "K",          "objective",
                                        "ratio",           "dog_max", "stitch_gap", "folded",
                                        "handle_distance", "facts",   "shape_s",    "total_s",
                                        "iterations",      "failure"};
  std::printf("%-18s %-6s %4s %10s %6s %8s %8s %6s %9s %6s %8s %8s\n", "pattern", "res", "K",
              "objective", "ratio", "dog_max", "gap", "folded", "handle_d", "facts", "shape_s",
              "total_s");
  std::string csv = csv_line(header);
  const bool tty = isatty(fileno(stderr));
  for_each_case(a, [&](const std::string& pattern, const std::string& res, const DogModel& model) {
    std::vector<PaceResult> results;
    for (int k : a.ks) {
      if (tty) std::fprintf(stderr, "\r  %s %s: K = %d ...   ", pattern.c_str(), res.c_str(), k);
      results.push_back(run_pace(model, config, k, a.max_hold));
    }
    if (tty) std::fprintf(stderr, "\r%70s\r", "");
    const std::vector<double> ratios = objective_ratios(results);
    const std::string name = std::filesystem::path(pattern).stem().string();
    for (size_t i = 0; i < results.size(); ++i) {
      const PaceResult& r = results[i];
      const std::string shape = r.time_to_shape_s ? fixed(*r.time_to_shape_s, 2) : "-";
      std::printf("%-18s %-6s %4d %10.5f %6.3f %8.1e %8.1e %6s %9.2e %6ld %8s %8.2f%s\n",
                  name.c_str(), res.c_str(), r.k, r.objective, ratios[i], r.dog_max,
                  r.stitch_gap_max, r.folded ? "yes" : "no", r.handle_distance, r.factorizations,
                  shape.c_str(), r.total_s,
                  r.failure.empty() ? "" : ("  failed: " + r.failure).c_str());
      csv += csv_line({name, res, std::to_string(r.k), general(r.objective), general(ratios[i]),
                       general(r.dog_max), general(r.stitch_gap_max), r.folded ? "1" : "0",
                       general(r.handle_distance), std::to_string(r.factorizations),
                       r.time_to_shape_s ? general(*r.time_to_shape_s) : "", general(r.total_s),
                       std::to_string(r.iterations), r.failure});
      std::fflush(stdout);
    }
  });
  write_csv(out, csv_name, csv);
}

// Per pattern, resolution, angle and K: the fold scenario over K iterations, then held until
// converged; the median times of --repeat runs, the rest from the first (runs are deterministic).
void bench_fold(const BenchArgs& a, std::unique_ptr<OutputSet>& out, const std::string& csv_name) {
  if (a.patterns.empty() || a.resolutions.empty())
    throw UsageError("--fold: give --pattern and --res");
  RunConfig config = paced_config(a);
  const std::vector<int> ks = a.ks_opt->count() ? a.ks : std::vector<int>{1};
  const int repeat = a.repeat_opt->count() ? a.repeat : 1;
  const std::vector<std::string> header{"pattern",     "res",        "angle",      "K",
                                        "shape_s",     "total_s",    "facts",      "agreement",
                                        "bent",        "targeted",   "tip_sites",  "tip_against",
                                        "angle_error", "dog_max",    "stitch_gap", "sheet_strain",
                                        "converged",   "iterations", "failure"};
  std::printf("%-28s %-6s %6s %4s %8s %8s %6s %9s %11s %9s %9s %8s %8s %7s %5s\n", "pattern", "res",
              "angle", "K", "shape_s", "total_s", "facts", "agreement", "bent/sites", "tip",
              "angle_err", "dog_max", "gap", "strain", "conv");
  std::string csv = csv_line(header);
  const bool tty = isatty(fileno(stderr));
  for_each_case(a, [&](const std::string& pattern, const std::string& res, const DogModel& model) {
    const std::string name = std::filesystem::path(pattern).stem().string();
    for (double angle : a.angles)
      for (int k : ks) {
        config.fold_angle = angle;
        std::vector<PaceResult> runs;
        std::vector<double> shape, total;
        for (int i = 0; i < repeat; ++i) {
          if (tty)
            std::fprintf(stderr, "\r  %s %s %g degrees K = %d: run %d/%d ...   ", name.c_str(),
                         res.c_str(), angle, k, i + 1, repeat);
          runs.push_back(run_fold_pace(model, config, k, a.max_hold));
          if (runs.back().time_to_shape_s) shape.push_back(*runs.back().time_to_shape_s);
          total.push_back(runs.back().total_s);
        }
        if (tty) std::fprintf(stderr, "\r%90s\r", "");
        const PaceResult& r = runs.front();
        const AngleAgreement& m = r.angles;
        const bool all_shaped = shape.size() == runs.size();
        const std::string shape_s = all_shaped ? fixed(median_of(shape), 2) : "-";
        const std::string agreement =
            m.bent_sites > 0 ? fixed(100 * m.direction_agreement(), 1) + "%" : "-";
        const std::string tip =
            m.tip_sites > 0 ? std::to_string(m.tip_against) + "/" + std::to_string(m.tip_sites)
                            : std::string("-");
        std::printf(
            "%-28s %-6s %6g %4d %8s %8.2f %6ld %9s %5d/%-5d %9s %9.2f %8.1e %8.1e %6.1f%% "
            "%5s%s\n",
            name.c_str(), res.c_str(), angle, k, shape_s.c_str(), median_of(total),
            r.factorizations, agreement.c_str(), m.bent_sites, m.targeted_sites, tip.c_str(),
            m.median_error, r.dog_max, r.stitch_gap_max, 100 * r.sheet_strain_max,
            r.converged ? "yes" : "no",
            r.failure.empty() ? "" : ("  failed: " + r.failure).c_str());
        csv += csv_line({name, res, general(angle), std::to_string(k),
                         all_shaped ? general(median_of(shape)) : "", general(median_of(total)),
                         std::to_string(r.factorizations),
                         m.bent_sites > 0 ? general(m.direction_agreement()) : "",
                         std::to_string(m.bent_sites), std::to_string(m.targeted_sites),
                         std::to_string(m.tip_sites), std::to_string(m.tip_against),
                         general(m.median_error), general(r.dog_max), general(r.stitch_gap_max),
                         general(r.sheet_strain_max), r.converged ? "1" : "0",
                         std::to_string(r.iterations), r.failure});
        std::fflush(stdout);
      }
  });
  write_csv(out, csv_name, csv);
}

void bench(const BenchArgs& a) {
  set_thread_count(a.threads);
  std::vector<ModeKind> modes;
  for (const auto& m : a.modes) modes.push_back(parse_enum<ModeKind>(m, "--modes: "));
  const std::vector<std::vector<Case>> places = bench_places(a, modes);
  std::unique_ptr<OutputSet> out;
  std::string csv_name;
  if (!a.csv.empty()) {
    const std::filesystem::path path(a.csv);
    out = std::make_unique<OutputSet>(path.has_parent_path() ? path.parent_path().string() : ".");
    csv_name = path.filename().string();
  }
  if (a.pace && a.fold) throw UsageError("--pace and --fold are two benchmarks: give one");
  if (a.pace) return bench_pace(a, out, csv_name);
  if (a.fold) return bench_fold(a, out, csv_name);
  if (!a.config.empty())
    throw UsageError(
        "--config: only with --pace or --fold (the timing benchmark runs the preset's settings)");
  RunConfig config;
  apply_preset_option(a.preset, a.thesis_grid, config);
  config.iterations = a.iterations;
  config.hold = a.iterations / 5;
  std::printf("%-18s %-6s %-9s %6s %6s %9s %9s %6s %9s %7s %10s %9s %7s\n", "pattern", "res",
              "mode", "verts", "dof", "median_ms", "ms/dof", "steps", "factor_ms", "facts",
              "objective", "dog_max", "speedup");
  const bool tty = isatty(fileno(stderr));
  std::string csv = csv_line(bench_columns());
  for (const auto& cases : places) {
    std::vector<std::unique_ptr<CaseProgress>> progress;
    RoundsOptions options;
    options.repeat = a.repeat;
    options.record_problems = false;
    options.observers = [&](const Case& c, int round) -> std::vector<RunObserver*> {
      if (!tty) return {};
      progress.push_back(
          std::make_unique<CaseProgress>(c, round, a.repeat, config.iterations + config.hold));
      return {progress.back().get()};
    };
    const std::vector<CaseResult> results = run_rounds(cases, config, options);
    if (tty) std::fprintf(stderr, "\r%70s\r", "");
    for (const auto& r : results) {
      print_row(r);
      csv += csv_line(bench_fields(r));
    }
    if (a.trim && !results.empty()) {
      const TrimCost t = measure_trim_cost(build_case_model(cases.front()).fine, 21);
      std::printf(
          "  trimmed surface: %d triangles, topology %.1f ms once, %.2f ms per state (%.2f%% of a "
          "%s iteration)\n",
          t.triangles, t.build_ms, t.state_ms, 100 * t.state_ms / results.front().median_ms,
          enum_name(cases.front().mode));
    }
  }
  write_csv(out, csv_name, csv);
}

}  // namespace

void register_bench_command(CLI::App& app, Runner& runner) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Time solver modes on the thesis protocol (median ms per iteration over iterations 10-240); "
      "with --pace the corners drag at several paces, with --fold the fold of crease patterns");
  cmd->add_option("--pattern", a->patterns, "crease pattern(s) (SVG or FOLD)");
  cmd->add_option("--res", a->resolutions, "resolution(s) XxY");
  cmd->add_option("--modes", a->modes, "solver mode(s)")->delimiter(',')->capture_default_str();
  add_case_grid_options(*cmd, *a);
  cmd->add_option("--iters", a->iterations,
                  "moving iterations of the protocol (hold: a fifth of that)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  a->repeat_opt =
      cmd->add_option("--repeat", a->repeat,
                      "runs per case (the median of their medians is reported; --fold: the median "
                      "times, 1 run unless given)")
          ->check(CLI::Range(1, 1000))
          ->capture_default_str();
  cmd->add_option("--threads", a->threads, "threads (0: one per core)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_option("--csv", a->csv, "also write the table as CSV to this file");
  cmd->add_flag("--trim", a->trim,
                "also time the trimmed surface of each case's fine mesh (its topology, and each "
                "state: positions, "
                "normals and a frame's arrays), against the first mode's median iteration");
  cmd->add_flag("--pace", a->pace,
                "the pace benchmark: the standard mode's corners drag over each of --ks "
                "iterations, then held "
                "until converged (at most --max-hold); per K the final objective and its ratio to "
                "the best K, "
                "the residuals, the handles' distance to their targets, factorisations and the "
                "time to shape");
  cmd->add_flag("--fold", a->fold,
                "the fold benchmark: per pattern, resolution, --angles and --ks (default 1: the "
                "targets at once) "
                "the standard mode's fold scenario, held until converged (at most --max-hold); the "
                "time to shape, "
                "factorisations, the share of bent fold sites bent the drawn way, the median angle "
                "error, residuals, "
                "the strain of the paper");
  a->ks_opt =
      cmd->add_option("--ks", a->ks, "--pace, --fold: iterations over which the targets move")
          ->delimiter(',')
          ->check(CLI::Range(1, 100000))
          ->capture_default_str();
  cmd->add_option("--angles", a->angles,
                  "--fold: fold angles (degrees; each crease's own angle wins)")
      ->delimiter(',')
      ->check(CLI::Range(-180.0, 180.0))
      ->capture_default_str();
  cmd->add_option("--config", a->config,
                  "--pace, --fold: JSON file of weights and solver options (as for sdog run), "
                  "applied after --preset; "
                  "the benchmark sets the scenario, iterations, hold and mode");
  cmd->add_option("--max-hold", a->max_hold, "--pace, --fold: held iterations at most")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  cmd->callback([a, &runner]() { runner = [a]() { bench(*a); }; });
}

}  // namespace sdog::cli
