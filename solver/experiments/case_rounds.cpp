#include "solver/experiments/case_rounds.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <numeric>

#include "base/errors.h"
#include "base/statistics.h"
#include "geometry/input/pattern_file.h"
#include "solver/run/run_setup.h"
#include "solver/run/run_totals.h"

namespace sdog {
namespace {

// The series of one run, besides its totals.
struct SeriesRecorder : RunObserver {
  std::vector<SeriesPoint> points;
  void on_iteration(const IterationReport& r, const Dofs&) override {
    const Diagnostics& d = r.diagnostics;
    points.push_back({r.iteration, d.objective, r.iteration_ms, d.dog_max, d.stitch_gap_max});
  }
};

// One case while its rounds run.
struct CaseRuns {
  CaseResult result;
  std::optional<DogModel> model;
  bool stopped = false;  // skipped or failed: no more runs
};

// Called from an exception handler: rethrows the exception being handled unless problems are
// recorded.
void skip(CaseRuns& runs, const std::string& why, bool record) {
  if (!record) throw;
  runs.result.status = CaseStatus::kSkipped;
  runs.result.note = why;
  runs.result.series.clear();
  runs.stopped = true;
}

CaseRuns start_case(const Case& c, bool record) {
  CaseRuns runs;
  CaseResult& r = runs.result;
  r.pattern = std::filesystem::path(c.pattern).stem().string();
  r.res = c.res;
  r.mode = c.mode;
  try {
    runs.model = build_case_model(c);
  } catch (const UsageError& e) {
    skip(runs, e.what(), record);
    return runs;
  }
  r.vertices = runs.model->fine.vertex_count();
  r.dof = 3 * r.vertices;
  return runs;
}

void record_run(CaseResult& r, const RunSummary& s, const RunTotals& totals,
                SeriesRecorder& series) {
  r.series = std::move(series.points);
  r.iterations = s.iterations;
  r.final_objective = s.last.diagnostics.objective;
  r.dog_max = s.last.diagnostics.dog_max;
  r.stitch_gap_max = s.last.diagnostics.stitch_gap_max;
  r.folded = s.last.step.folded;
  r.dog_max_run = std::max(r.dog_max_run, totals.worst_dog);
  r.round_ms.push_back(totals.median_window_ms());
  r.median_ms = median(r.round_ms);
  r.round_total_s.push_back(
      std::accumulate(totals.iteration_ms.begin(), totals.iteration_ms.end(), 0.0) / 1000);
  r.total_s = median(r.round_total_s);
  r.window_work += totals.window_work;
  r.window_iterations += totals.window_iterations;
}

void run_once(CaseRuns& runs, const RunConfig& config, std::vector<RunObserver*> observers,
              bool record) {
  CaseResult& r = runs.result;
  RunTotals totals;
  SeriesRecorder series;
  observers.push_back(&totals);
  observers.push_back(&series);
  RunSummary s;
  try {
    RunSetup setup(*runs.model, r.mode, config);
    s = setup.run(observers);
  } catch (const UsageError& e) {
    return skip(runs, e.what(), record);
  } catch (const SolverError& e) {
    return skip(runs, e.what(), record);
  }
  record_run(r, s, totals, series);
  if (!s.failed()) return;
  if (!record)
    throw SolverError(r.pattern + " " + r.res + " " + enum_name(r.mode) + ": " + s.failure);
  r.status = CaseStatus::kFailed;
  r.note = s.failure;
  runs.stopped = true;
}

}  // namespace

DogModel build_case_model(const Case& c) {
  MeshOptions mesh_options;
  mesh_options.build_coarse = mode_needs_coarse(c.mode);
  return build_dog_model(read_crease_pattern(c.pattern), parse_resolution(c.res), mesh_options);
}

std::vector<CaseResult> run_rounds(const std::vector<Case>& cases, const RunConfig& config,
                                   const RoundsOptions& options) {
  std::vector<CaseRuns> runs;
  for (const auto& c : cases) runs.push_back(start_case(c, options.record_problems));
  for (int round = 0; round < std::max(1, options.repeat); ++round)
    for (size_t i = 0; i < cases.size(); ++i)
      if (!runs[i].stopped)
        run_once(
            runs[i], config,
            options.observers ? options.observers(cases[i], round) : std::vector<RunObserver*>{},
            options.record_problems);
  std::vector<CaseResult> results;
  for (auto& r : runs) results.push_back(std::move(r.result));
  relate_to_standard(results);
  return results;
}

void relate_to_standard(std::vector<CaseResult>& results) {
  std::map<std::pair<std::string, std::string>, const CaseResult*> standard;
  for (const auto& r : results)
    if (r.mode == ModeKind::kStandard && r.completed()) standard[{r.pattern, r.res}] = &r;
  for (auto& r : results) {
    r.objective_ratio.reset();
    r.speedup.reset();
    r.total_speedup.reset();
    r.speedup_paired.reset();
    const auto it = standard.find({r.pattern, r.res});
    if (!r.completed() || it == standard.end()) continue;
    const CaseResult& s = *it->second;
    r.objective_ratio = r.final_objective / s.final_objective;
    r.speedup = s.median_ms / r.median_ms;
    r.total_speedup = s.total_s / r.total_s;
    r.speedup_paired = paired_ratio(s.round_ms, r.round_ms);
  }
}

std::vector<Case> thesis_grid(const std::string& dir, ModeKind mode) {
  const std::pair<const char*, std::vector<const char*>> grid[] = {
      {"1_curve", {"31x21", "43x31", "55x41", "81x59"}},
      {"4_corners", {"21x21", "41x41", "61x61", "81x81"}},
      {"valley", {"21x21", "41x41", "61x61", "81x81"}},
      {"parallel_curves_4", {"27x45", "39x65", "45x75", "51x85"}}};
  std::vector<Case> cases;
  for (const auto& [name, resolutions] : grid) {
    const std::string path = dir + "/" + name + ".svg";
    if (!std::filesystem::exists(path))
      throw InputError(path +
                       ": thesis pattern not found (pass the folder of the thesis patterns with "
                       "--patterns-dir)");
    for (const char* res : resolutions) cases.push_back({path, res, mode});
  }
  return cases;
}

}  // namespace sdog
