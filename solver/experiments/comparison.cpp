#include "solver/experiments/comparison.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <numeric>

#include "base/errors.h"

namespace sdog {
namespace {

// The series and the timing of one run.
struct SeriesRecorder : RunObserver {
  std::vector<ComparePoint> points;
  std::vector<double> iteration_ms;
  double worst_dog = 0;
  void on_iteration(const IterationReport& r, const Dofs&) override {
    const Diagnostics& d = r.diagnostics;
    points.push_back({r.iteration, d.objective, r.iteration_ms, d.dog_max, d.stitch_gap_max});
    iteration_ms.push_back(r.iteration_ms);
    worst_dog = std::max(worst_dog, d.dog_max);
  }
};

CompareRow skipped(CompareRow row, const std::string& why) {
  row.status = CompareStatus::Skipped;
  row.note = why;
  row.series.clear();
  return row;
}

}  // namespace

const char* to_string(CompareStatus s) {
  switch (s) {
    case CompareStatus::Completed:
      return "completed";
    case CompareStatus::Failed:
      return "failed";
    case CompareStatus::Skipped:
      return "skipped";
  }
  return "?";
}

namespace {

// One case of a comparison while its rounds run.
struct CaseRuns {
  CompareRow row;
  std::optional<DogModel> model;
  std::vector<double> totals;  // seconds per completed run
  bool stopped = false;        // skipped or failed: no more runs
};

CaseRuns start_case(const BenchCase& c) {
  CaseRuns runs;
  CompareRow& row = runs.row;
  row.pattern = std::filesystem::path(c.pattern).stem().string();
  row.res = c.res;
  row.mode = c.mode;
  try {
    runs.model = build_case_model(c);
  } catch (const UsageError& e) {
    row = skipped(row, e.what());
    runs.stopped = true;
    return runs;
  }
  row.vertices = runs.model->fine.vertex_count();
  row.dof = 3 * row.vertices;
  return runs;
}

void run_once(CaseRuns& runs, const RunConfig& config, std::vector<RunObserver*> observers) {
  CompareRow& row = runs.row;
  SeriesRecorder recorder;
  observers.push_back(&recorder);
  RunSummary s;
  try {
    s = run_case(*runs.model, row.mode, config, observers);
  } catch (const UsageError& e) {
    row = skipped(row, e.what());
    runs.stopped = true;
    return;
  } catch (const SolverError& e) {
    row = skipped(row, e.what());
    runs.stopped = true;
    return;
  }
  row.series = std::move(recorder.points);
  row.iterations = s.iterations;
  row.final_objective = s.last.diagnostics.objective;
  row.dog_max = s.last.diagnostics.dog_max;
  row.stitch_gap_max = s.last.diagnostics.stitch_gap_max;
  row.folded = s.last.step.folded;
  row.dog_max_run = std::max(row.dog_max_run, recorder.worst_dog);
  row.round_ms.push_back(median_iteration_ms(recorder.iteration_ms));
  row.median_ms = median(row.round_ms);
  runs.totals.push_back(std::accumulate(recorder.iteration_ms.begin(), recorder.iteration_ms.end(), 0.0) / 1000);
  row.total_s = median(runs.totals);
  if (s.failed) {
    row.status = CompareStatus::Failed;
    row.note = s.failure;
    runs.stopped = true;
  }
}

}  // namespace

std::vector<CompareRow> run_compare_rounds(const std::vector<BenchCase>& cases, const RunConfig& config, int repeat,
                                           const ObserversOfRun& observers) {
  std::vector<CaseRuns> runs;
  for (const auto& c : cases) runs.push_back(start_case(c));
  for (int round = 0; round < std::max(1, repeat); ++round)
    for (size_t i = 0; i < cases.size(); ++i)
      if (!runs[i].stopped) run_once(runs[i], config, observers ? observers(cases[i], round) : std::vector<RunObserver*>{});
  std::vector<CompareRow> rows;
  for (auto& r : runs) rows.push_back(std::move(r.row));
  return rows;
}

void relate_to_standard(std::vector<CompareRow>& rows) {
  std::map<std::pair<std::string, std::string>, const CompareRow*> standard;
  for (const auto& r : rows)
    if (r.mode == "standard" && r.completed()) standard[{r.pattern, r.res}] = &r;
  for (auto& r : rows) {
    r.objective_ratio.reset();
    r.speedup.reset();
    r.total_speedup.reset();
    r.speedup_paired.reset();
    const auto it = standard.find({r.pattern, r.res});
    if (!r.completed() || it == standard.end()) continue;
    const CompareRow& s = *it->second;
    r.objective_ratio = r.final_objective / s.final_objective;
    r.speedup = s.median_ms / r.median_ms;
    r.total_speedup = s.total_s / r.total_s;
    r.speedup_paired = paired_speedup(s.round_ms, r.round_ms);
  }
}

std::vector<std::string> compare_columns() {
  return {"pattern", "res",     "mode",        "vertices",       "dof",    "iterations",
          "final_objective", "objective_ratio", "median_ms", "speedup", "total_s", "total_speedup", "speedup_paired",
          "dog_max", "dog_max_run", "stitch_gap_max", "folded", "status", "note"};
}

std::vector<std::string> compare_fields(const CompareRow& r) {
  std::vector<std::string> f{r.pattern, r.res, r.mode};
  if (r.status == CompareStatus::Skipped) {
    f.resize(compare_columns().size() - 2);
  } else {
    f.insert(f.end(), {std::to_string(r.vertices), std::to_string(r.dof), std::to_string(r.iterations),
                       csv_number(r.final_objective, 9), optional_csv_number(r.objective_ratio, 9),
                       csv_number(r.median_ms, 4), optional_csv_number(r.speedup, 4), csv_number(r.total_s, 4),
                       optional_csv_number(r.total_speedup, 4), optional_csv_number(r.speedup_paired, 4),
                       csv_number(r.dog_max, 3), csv_number(r.dog_max_run, 3), csv_number(r.stitch_gap_max, 3),
                       r.folded ? "1" : "0"});
  }
  f.push_back(to_string(r.status));
  f.push_back(r.note);
  return f;
}

std::string series_csv_header() { return "pattern,res,mode,iteration,objective,ms,dog_max,stitch_gap_max\n"; }

std::string series_csv_rows(const CompareRow& r) {
  std::string out;
  for (const auto& p : r.series)
    out += csv_line({r.pattern, r.res, r.mode, std::to_string(p.iteration), csv_number(p.objective, 9),
                     csv_number(p.ms, 4), csv_number(p.dog_max, 3), csv_number(p.stitch_gap_max, 3)});
  return out;
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (size_t i = 0; i < fields.size(); ++i) {
    const std::string& f = fields[i];
    if (i) line += ',';
    if (f.find_first_of(",\"\n") == std::string::npos) {
      line += f;
      continue;
    }
    line += '"';
    for (char ch : f) line += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    line += '"';
  }
  return line + "\n";
}

}  // namespace sdog
