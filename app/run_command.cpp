// sdog run: a deformation run (scenario, mode) with its run log, run.json, frames and the trimmed
// surface of each frame (VTK, and OBJ / PLY with --export).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/progress.h"
#include "app/saved_run.h"
#include "app/threads.h"
#include "app/versions.h"
#include "base/atomic_output.h"
#include "base/errors.h"
#include "base/statistics.h"
#include "base/text_format.h"
#include "geometry/input/fold_writer.h"
#include "geometry/pattern/fold_tips.h"
#include "solver/config/run_config_json.h"
#include "solver/problem/crease_angles.h"
#include "solver/run/crease_settings.h"
#include "solver/run/run_log.h"
#include "solver/run/run_setup.h"
#include "solver/run/run_totals.h"
#include "ui/vis/frame_writer.h"
#include "ui/vis/surface_series.h"

namespace sdog::cli {
namespace {

struct RunArgs {
  PatternOptions pattern;
  std::string mode = "standard";
  std::vector<std::string> switches;  // "ITER:MODE"
  std::string scenario = "corners";
  std::string config;
  std::string preset;
  std::string out;
  std::string exports;  // --export obj,ply
  std::string export_colour = "patches";
  double angle = 90;
  double fold_percent = 100;
  ScheduleOptions schedule;
  int frames_every = 10;
  int threads = 0;
  bool keep_failed = false;
  bool quiet = false;
  double link_weight = 0;
  bool no_fine_to_coarse = false;
  CLI::Option* link_weight_opt = nullptr;
  CLI::Option *scenario_opt = nullptr, *angle_opt = nullptr, *fold_percent_opt = nullptr;
  double rho = 1, gamma = 1;  // the ADMM modes
  CLI::Option *rho_opt = nullptr, *gamma_opt = nullptr;
  CLI::Option *export_opt = nullptr, *export_colour_opt = nullptr;
};

std::atomic<bool> g_cancel{false};
void on_interrupt(int) {
  g_cancel = true;
}

nlohmann::json diagnostics_json(const IterationReport& r) {
  const Diagnostics& d = r.diagnostics;
  nlohmann::json terms;
  for (int k = 0; k < kTermCount; ++k) terms[term_name(k)] = d.terms[k];
  nlohmann::json j = {{"iteration", r.iteration},
                      {"t", r.t},
                      {"objective", d.objective},
                      {"objective_final_targets", r.objective_final_targets},
                      {"terms_unweighted", terms},
                      {"dog_max", d.dog_max},
                      {"dog_l2", d.dog_l2},
                      {"stitch_gap_max", d.stitch_gap_max},
                      {"edge_strain_max", d.edge_strain_max},
                      {"sheet_strain_max", d.sheet_strain_max},
                      {"folded", r.step.folded}};
  const AngleAgreement& a = d.angles_met;
  if (a.targeted_sites > 0)
    j["fold_angles"] = {
        {"targeted_sites", a.targeted_sites},     {"bent_sites", a.bent_sites},
        {"bent_as_targeted", a.bent_as_targeted}, {"direction_agreement", a.direction_agreement()},
        {"median_angle_error", a.median_error},   {"fold_tip_sites", a.tip_sites},
        {"fold_tip_sites_against", a.tip_against}};
  return j;
}

nlohmann::json creases_json(const DogModel& model, const std::vector<CreaseFold>& creases) {
  nlohmann::json out = nlohmann::json::array();
  for (const CreaseFold& c : creases)
    out.push_back({{"crease", c.curve},
                   {"id", model.fine.stitching.curves[c.curve].id},
                   {"assignment", enum_name(model.fine.stitching.curves[c.curve].fold)},
                   {"sites", c.sites},
                   {"bent", c.bent},
                   {"against_target", c.against},
                   {"target_angle", c.target},
                   {"median_angle", c.angle},
                   {"median_angle_error", c.median_error}});
  return out;
}

// "--switch 100:twolevel" (repeatable) as mode switches; UsageError naming the bad one.
std::vector<ModeSwitch> parse_switches(const std::vector<std::string>& texts) {
  std::vector<ModeSwitch> out;
  for (const std::string& t : texts) {
    const size_t colon = t.find(':');
    int k = 0;
    size_t used = 0;
    try {
      if (colon != std::string::npos) k = std::stoi(t.substr(0, colon), &used);
    } catch (const std::exception&) {  // not a number, or out of int's range
      used = 0;
    }
    if (colon == std::string::npos || used != colon || k < 1)
      throw UsageError(
          "--switch: expected ITERATION:MODE with ITERATION >= 1 (e.g. 100:twolevel), got '" + t +
          "'");
    out.push_back({k, parse_enum<ModeKind>(t.substr(colon + 1), "--switch " + t + ": ")});
  }
  return out;
}

// --export and --export-colour; UsageError before any work.
vis::SurfaceExport surface_export(const RunArgs& a) {
  vis::SurfaceExport exports;
  if (a.export_opt->count()) {
    exports.formats = vis::parse_surface_formats(a.exports, "--export: ");
    if (a.out.empty()) throw UsageError("--export writes into the --out directory: add --out DIR");
  }
  exports.colour = vis::parse_colour_layer(a.export_colour, "--export-colour: ");
  const bool ply = std::find(exports.formats.begin(), exports.formats.end(),
                             vis::SurfaceFormat::kPly) != exports.formats.end();
  if (a.export_colour_opt->count() && !ply)
    throw UsageError("--export-colour colours the PLY files: add --export ply");
  return exports;
}

// "surface.obj and 4 surface_NNNN.obj, ..." for the formats written.
std::string export_files_text(const vis::SurfaceSeries& surfaces, bool with_frames) {
  std::string text;
  for (vis::SurfaceFormat f : surfaces.exports().formats) {
    const std::string ext = enum_name(f);
    text += ", surface." + ext;
    if (with_frames)
      text += " and " + std::to_string(surfaces.frame_count()) + " surface_NNNN." + ext;
  }
  return text;
}

RunConfig run_config(const RunArgs& a) {
  RunConfig config;
  apply_preset_option(a.preset, false, config);
  if (!a.config.empty()) read_run_config(a.config, config);
  if (a.scenario_opt->count() || a.config.empty())
    config.scenario = parse_enum<ScenarioKind>(a.scenario, "--scenario: ");
  if (a.schedule.iterations_opt->count()) config.iterations = a.schedule.iterations;
  if (a.schedule.hold_opt->count()) config.hold = a.schedule.hold;
  if (a.angle_opt->count()) config.fold_angle = a.angle;
  if (a.fold_percent_opt->count()) config.fold_percent = a.fold_percent;
  if (a.link_weight_opt->count())
    config.coarse.link_weight = config.twolevel.link_weight = a.link_weight;
  if (a.no_fine_to_coarse) config.coarse.fine_to_coarse = false;
  if (a.rho_opt->count()) config.admm.rho = a.rho;
  if (a.gamma_opt->count()) config.admm.gamma = a.gamma;
  if (!a.switches.empty()) config.switches = parse_switches(a.switches);
  validate_run_config(config,
                      a.config.empty() ? "command line" : a.config + " with the command line",
                      a.config.empty() ? ErrorKind::kUsage : ErrorKind::kInput);
  return config;
}

nlohmann::json run_json(const RunArgs& a, RunSetup& setup, const RunSummary& summary,
                        const RunTotals& totals) {
  const DogModel& model = setup.model();
  const Scenario& scenario = setup.scenario();
  nlohmann::json j = {{"status", enum_name(summary.termination)},
                      {"pattern", a.pattern.pattern},
                      {"resolution",
                       {{"fine", model.fine_res.str()},
                        {"coarse", model.has_coarse ? model.coarse_res.str() : ""}}},
                      {"mesh",
                       {{"vertices", model.fine.vertex_count()},
                        {"quads", model.fine.quad_count()},
                        {"patches", model.fine.patch_count()},
                        {"dof", 3 * model.fine.vertex_count()},
                        {"dog_constraint_rows", setup.problem().dog.row_count()}}},
                      {"mode", a.mode},
                      {"config", to_json(setup.config())},
                      {"scenario",
                       {{"name", scenario.name},
                        {"position_constraints", scenario.positions.size()},
                        {"angle_constraints", scenario.angles.size()}}},
                      {"threads", a.threads},
                      {"software", software_versions()},
                      {"totals",
                       {{"iterations", summary.iterations},
                        {"seconds", summary.seconds},
                        {"median_iteration_ms", median(totals.iteration_ms)},
                        {"factorizations", totals.work.factorizations},
                        {"sqp_steps", totals.work.steps},
                        {"fold_retries", totals.work.fold_retries},
                        {"recovered_failures", totals.work.recovered_failures},
                        {"factor_ms", totals.work.factor_ms},
                        {"dog_max_over_run", totals.worst_dog},
                        {"iterations_above_dog_tolerance", totals.dog_misses}}},
                      {"final", diagnostics_json(summary.last)}};
  if (!scenario.angles.empty())
    j["creases"] = creases_json(model, crease_folds(setup.problem(), setup.positions()));
  if (summary.failed()) j["failure"] = summary.failure;
  add_model_record(j, a.pattern);
  return j;
}

void report_success(const RunArgs& a, RunSetup& setup, const RunSummary& summary,
                    const RunTotals& totals, double seconds) {
  const RunConfig& config = setup.config();
  const DogModel& model = setup.model();
  const IterationReport& last = summary.last;
  std::string modes = a.mode;
  for (const ModeSwitch& s : config.switches)
    modes +=
        std::string(", ") + enum_name(s.mode) + " from iteration " + std::to_string(s.iteration);
  const double final_tolerance = config.standard.sqp.final_constraint_tolerance;
  const bool within = within_final_tolerance(last.diagnostics, final_tolerance);
  std::cout << "sdog run: " << summary.iterations << " iterations of " << modes << " ("
            << setup.scenario().name << ") on " << a.pattern.pattern << " " << model.fine_res.str()
            << " (" << model.fine.vertex_count() << " vertices) in " << format_number(seconds)
            << " s, median " << format_number(median(totals.iteration_ms)) << " ms/iteration\n"
            << "final: objective " << format_number(last.diagnostics.objective) << ", DOG max "
            << format_number(last.diagnostics.dog_max) << " (worst over the run "
            << format_number(totals.worst_dog) << "), stitch gap "
            << format_number(last.diagnostics.stitch_gap_max)
            << (setup.problem().free_sites.empty() ? ""
                : !within                          ? ""
                : last.step.folded                 ? ", folded"
                                                   : ", NOT folded")
            << (within ? "" : ", NOT within the final tolerance") << "\n";
  if (!within)
    std::cerr << "warning: the final state misses the final constraint tolerance "
              << format_number(final_tolerance) << " (DOG residual "
              << format_number(last.diagnostics.dog_max) << ", stitch gap "
              << format_number(last.diagnostics.stitch_gap_max)
              << "): more iterations, --hold or a longer last projection (solver option "
                 "projection_steps, and "
                 "polish_factorizations 0) may reach it\n";
  const AngleAgreement& met = last.diagnostics.angles_met;
  if (met.targeted_sites > 0)
    std::cout << "fold angles: " << met.bent_as_targeted << " of the " << met.bent_sites
              << " fold sites bent more than " << format_number(kBentDegrees) << " degrees (of "
              << met.targeted_sites << " with a target) bend the way their target says ("
              << format_number(std::round(1000 * met.direction_agreement()) / 10)
              << "%), median angle error " << format_number(met.median_error) << " degrees"
              << (met.tip_sites == 0
                      ? std::string()
                      : "; " + std::to_string(met.tip_sites) + " more sites within " +
                            format_number(kFoldTipRadius) + " grid edges of a fold tip, " +
                            std::to_string(met.tip_against) + " of them bent against their target")
              << "\n";
  for (const CreaseFold& c : crease_folds(setup.problem(), setup.positions()))
    if (c.against > 0)
      std::cerr << "warning: crease " << c.curve << " (" << model.clean.creases[c.curve].origin
                << ") folds against its target (" << format_number(c.target) << " degrees) at "
                << c.against << " of its " << c.bent << " bent fold sites"
                << (c.against_near_tip == 0 ? std::string()
                    : c.against_near_tip == c.against
                        ? std::string(", all next to a fold tip (see above)")
                        : ", " + std::to_string(c.against_near_tip) +
                              " of them next to a fold tip (see above)")
                << "\n";
  const Diagnostics& d = last.diagnostics;
  if (d.sheet_strain_max > kStretchedStrain)
    std::cerr << "warning: the sheet stretches: an edge of patch " << d.sheet_strain_patch << " is "
              << format_number(std::round(1000 * std::abs(d.sheet_strain_worst)) / 10) << "% "
              << (d.sheet_strain_worst < 0 ? "shorter" : "longer")
              << " than drawn (sheet_strain_max; the frames' edge_strain shows where): paper does "
                 "not stretch, and the "
                 "targets ask for more than the sheet gives without it (smaller fold angles or "
                 "--fold-percent, targets "
                 "closer to the sheet, or a larger isometry weight stretch it less)\n";
  if (totals.dog_misses > 0)
    std::cerr << "warning: the DOG constraints stayed above the solver's tolerance "
              << format_number(config.standard.sqp.constraint_tolerance) << " after "
              << totals.dog_misses << " of " << summary.iterations << " iterations (worst "
              << format_number(totals.worst_dog) << " at iteration " << totals.worst_iteration
              << "): the targets may ask for stretching (see dog_max in run.csv)\n";
}

void run(const RunArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  const ModeKind mode = parse_enum<ModeKind>(a.mode, "--mode: ");
  set_thread_count(a.threads);
  const RunConfig config = run_config(a);
  const vis::SurfaceExport exports = surface_export(a);
  // Fail on an unusable output directory before the work, not after it.
  std::unique_ptr<OutputSet> out;
  if (!a.out.empty()) out = std::make_unique<OutputSet>(a.out);

  DogModel model = build_model(a.pattern);
  apply_crease_settings(config.creases, model);
  RunSetup setup(model, mode, config);
  const int total = setup.total_iterations();
  RunCsv csv;
  PatchesCsv patches;
  // The restoration allows a little slack over the tolerance only through rounding.
  RunTotals totals(2 * config.standard.sqp.constraint_tolerance);
  ProgressBar progress(total, !a.quiet);
  std::vector<RunObserver*> observers{&csv, &patches, &totals, &progress};
  std::unique_ptr<vis::FrameWriter> frames;
  std::unique_ptr<vis::SurfaceSeries> surfaces;
  if (out && (a.frames_every > 0 || !exports.formats.empty()))
    surfaces = std::make_unique<vis::SurfaceSeries>(model.fine, *out, exports);
  if (out && a.frames_every > 0) {
    frames =
        std::make_unique<vis::FrameWriter>(model, setup.problem(), *out, a.frames_every, total);
    frames->add_surfaces(*surfaces);
    frames->write_start(setup.positions());
    observers.push_back(frames.get());
  }

  g_cancel = false;
  auto previous = std::signal(SIGINT, on_interrupt);
  const RunSummary summary = setup.run(observers, &g_cancel);
  std::signal(SIGINT, previous);
  progress.finish();
  const bool completed = summary.termination == Termination::kCompleted;

  std::vector<std::string> files;
  if (out && (completed || a.keep_failed)) {
    out->write_text("run.csv", csv.text());
    if (!patches.empty()) out->write_text("patches.csv", patches.text());
    out->write_text("run.json", run_json(a, setup, summary, totals).dump(2) + "\n");
    out->write_text("creases.csv", creases_csv(model.fine, setup.scenario(), setup.positions()));
    out->write_text("pattern.fold", fold_text(model.clean));
    if (frames) frames->finish();
    if (surfaces) {
      surfaces->write_final(to_positions(setup.positions()),
                            vis::frame_arrays(model, setup.problem(), setup.positions()));
      surfaces->finish();
    }
    files = out->commit();
  }
  if (!completed) {
    std::string msg = summary.failed()
                          ? "the solver failed at " + summary.failure
                          : "cancelled after " + std::to_string(summary.iterations) + " iterations";
    if (out)
      msg += files.empty() ? " (nothing written to " + a.out +
                                 "; --keep-failed keeps the log and frames up to here)"
                           : " (log and frames up to here written to " + a.out + ")";
    throw SolverError(msg);
  }
  report_success(a, setup, summary, totals, seconds_since(start));
  if (out)
    std::cout << "wrote " << a.out << "/run.csv, " << (patches.empty() ? "" : "patches.csv, ")
              << "run.json, creases.csv, pattern.fold"
              << (frames ? ", frames.pvd and " + std::to_string(frames->frame_count()) +
                               " frame_NNNN.vtu, surface.pvd and " +
                               std::to_string(surfaces->frame_count()) + " surface_NNNN.vtp"
                         : "")
              << (surfaces ? export_files_text(*surfaces, frames != nullptr) : "") << "\n";
}

// --scenario, --angle and --fold-percent.
void add_scenario_options(CLI::App& cmd, RunArgs& a) {
  a.scenario_opt =
      cmd.add_option(
             "--scenario", a.scenario,
             "corners: the thesis protocol (first grid corner held, last one dragged); "
             "fold: every crease folds from flat towards its assignment, to its own angle or "
             "--angle; none: only the --config constraints; "
             "flatten: start with every crease folded to --angle, one corner held, nothing else "
             "asked (the thesis's ADMM test)")
          ->check(CLI::IsMember(enum_names<ScenarioKind>()))
          ->capture_default_str();
  a.angle_opt = cmd.add_option("--angle", a.angle,
                               "final dihedral angle of the fold scenario, start angle of the "
                               "flatten scenario (degrees)")
                    ->check(CLI::Range(-180.0, 180.0))
                    ->capture_default_str();
  a.fold_percent_opt =
      cmd.add_option("--fold-percent", a.fold_percent,
                     "fold scenario: fold every crease to this percentage of its angle (its own, "
                     "a FOLD file's "
                     "edges_foldAngle, or --angle), as Origami Simulator's fold percent")
          ->check(CLI::Range(0.0, 100.0))
          ->capture_default_str();
}

// The options of single modes: the coarse modes' links, the ADMM modes' penalties.
void add_mode_options(CLI::App& cmd, RunArgs& a) {
  a.link_weight_opt =
      cmd.add_option(
             "--link-weight", a.link_weight,
             "coarse, twolevel modes: weight of the link constraints between fine and coarse twins "
             "($.coarse.link_weight and $.twolevel.link_weight, default 0)")
          ->check(CLI::Range(0.0, 1e12));
  cmd.add_flag(
      "--no-fine-to-coarse", a.no_fine_to_coarse,
      "coarse mode: the coarse mesh is not pulled towards the fine one (one-way coupling)");
  a.rho_opt = cmd.add_option("--rho", a.rho,
                             "ADMM modes: penalty rho > 0 of the augmented terms ($.admm.rho)");
  a.gamma_opt = cmd.add_option("--gamma", a.gamma,
                               "jadmm, proxjadmm: multiplier damping gamma > 0 ($.admm.gamma)");
}

}  // namespace

void register_run_command(CLI::App& app, Runner& runner) {
  auto a = std::make_shared<RunArgs>();
  CLI::App* cmd =
      app.add_subcommand("run",
                         "Deform the DOG of a crease pattern with a solver mode over a scenario; "
                         "write the run log, run.json and VTK frames");
  add_pattern_options(*cmd, a->pattern);
  cmd->add_option("--mode", a->mode, "solver mode (" + known_names<ModeKind>() + ")")
      ->capture_default_str();
  cmd->add_option(
      "--switch", a->switches,
      "ITERATION:MODE: from that iteration on the run continues with MODE (repeatable, ascending; "
      "$.switches)");
  add_scenario_options(*cmd, *a);
  add_schedule_options(*cmd, a->schedule);
  cmd->add_option(
      "--config", a->config,
      "JSON file with constraints, iteration counts, weights and solver options (command-line "
      "options win); see docs/reference/configuration.md");
  add_preset_option(*cmd, a->preset);
  cmd->add_option(
      "--out", a->out,
      "directory for run.csv, run.json, creases.csv (the fold angle reached at each crease point), "
      "pattern.fold (the pattern as read, FOLD), frames.pvd and frame_NNNN.vtu, surface.pvd and "
      "surface_NNNN.vtp (the trimmed surface of "
      "each frame), and in the patch modes patches.csv (the per-patch timeline)");
  cmd->add_option("--frames-every", a->frames_every, "write a frame every K iterations (0: none)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  a->export_opt = cmd->add_option(
      "--export", a->exports,
      "FORMATS: a list of obj, ply, fold: also write the trimmed surface of the final state "
      "(surface.obj, surface.ply, surface.fold) and "
      "of every frame (surface_NNNN.obj, ...) into --out, in sheet units; fold is a FOLD folded "
      "form with the fold angles reached");
  a->export_colour_opt =
      cmd->add_option("--export-colour", a->export_colour,
                      "the vertex colours of the PLY files: the colours of this overlay (" +
                          vis::known_colour_layers() + ")")
          ->capture_default_str();
  cmd->add_option("--threads", a->threads,
                  "threads for parallel patch solves (0: one per core); results do not depend on "
                  "this (the standard factorisation uses SDOG_BLAS_THREADS, default 2, BLAS "
                  "threads; patch factorisations one each)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  add_mode_options(*cmd, *a);
  cmd->add_flag("--keep-failed", a->keep_failed,
                "write the log and frames even when the run fails or is cancelled");
  cmd->add_flag("-q,--quiet", a->quiet, "no progress bar");
  cmd->callback([a, &runner]() { runner = [a]() { run(*a); }; });
}

}  // namespace sdog::cli
