#include "solver/experiments/tables.h"

#include "base/csv.h"

namespace sdog {

std::vector<std::string> bench_columns() {
  return {
      "pattern",          "res",       "mode",      "vertices",        "dof",     "median_ms",
      "ms_per_dof",       "sqp_steps", "factor_ms", "final_objective", "dog_max", "factorizations",
      "dog_max_over_run", "repeats",   "speedup",   "speedup_paired"};
}

std::vector<std::string> bench_fields(const CaseResult& r) {
  const Work& w = r.window_work;
  return {r.pattern,
          r.res,
          enum_name(r.mode),
          std::to_string(r.vertices),
          std::to_string(r.dof),
          csv_number(r.median_ms, 4),
          csv_number(r.ms_per_dof(), 4),
          csv_number(r.per_window_iteration(w.steps), 4),
          csv_number(r.per_window_iteration(w.factor_ms), 4),
          csv_number(r.final_objective, 6),
          csv_number(r.dog_max, 3),
          csv_number(r.per_window_iteration(w.factorizations), 4),
          csv_number(r.dog_max_run, 3),
          std::to_string(r.round_ms.size()),
          csv_number(r.speedup, 4),
          csv_number(r.speedup_paired, 4)};
}

std::vector<std::string> compare_columns() {
  return {"pattern",
          "res",
          "mode",
          "vertices",
          "dof",
          "iterations",
          "final_objective",
          "objective_ratio",
          "median_ms",
          "speedup",
          "total_s",
          "total_speedup",
          "speedup_paired",
          "dog_max",
          "dog_max_run",
          "stitch_gap_max",
          "folded",
          "status",
          "note"};
}

std::vector<std::string> compare_fields(const CaseResult& r) {
  std::vector<std::string> f{r.pattern, r.res, enum_name(r.mode)};
  if (r.status == CaseStatus::kSkipped) {
    f.resize(compare_columns().size() - 2);
  } else {
    f.insert(
        f.end(),
        {std::to_string(r.vertices), std::to_string(r.dof), std::to_string(r.iterations),
         csv_number(r.final_objective, 9), csv_number(r.objective_ratio, 9),
         csv_number(r.median_ms, 4), csv_number(r.speedup, 4), csv_number(r.total_s, 4),
         csv_number(r.total_speedup, 4), csv_number(r.speedup_paired, 4), csv_number(r.dog_max, 3),
         csv_number(r.dog_max_run, 3), csv_number(r.stitch_gap_max, 3), r.folded ? "1" : "0"});
  }
  f.push_back(enum_name(r.status));
  f.push_back(r.note);
  return f;
}

std::vector<std::string> series_columns() {
  return {"pattern", "res", "mode", "iteration", "objective", "ms", "dog_max", "stitch_gap_max"};
}

std::string series_rows(const CaseResult& r) {
  std::string out;
  for (const auto& p : r.series)
    out += csv_line({r.pattern, r.res, enum_name(r.mode), std::to_string(p.iteration),
                     csv_number(p.objective, 9), csv_number(p.ms, 4), csv_number(p.dog_max, 3),
                     csv_number(p.stitch_gap_max, 3)});
  return out;
}

}  // namespace sdog
