#pragma once
// The tables of `sdog bench` (bench CSV) and `sdog compare` (compare.csv, series.csv): column
// names and the fields of a case result. docs/reference/output-files.md lists every column.
#include <string>
#include <vector>

#include "solver/experiments/case_rounds.h"

namespace sdog {

/// pattern, res, mode, vertices, dof, median_ms, ms_per_dof, sqp_steps, factor_ms,
/// final_objective, dog_max, factorizations, dog_max_over_run, repeats, speedup, speedup_paired.
std::vector<std::string> bench_columns();
std::vector<std::string> bench_fields(const CaseResult& r);

/// pattern, res, mode, vertices, dof, iterations, final_objective, objective_ratio, median_ms,
/// speedup, total_s, total_speedup, speedup_paired, dog_max, dog_max_run, stitch_gap_max, folded,
/// status, note. Empty fields for what a result does not have (ratios without standard, numbers of
/// a skipped case).
std::vector<std::string> compare_columns();
std::vector<std::string> compare_fields(const CaseResult& r);

/// series.csv (long format): pattern, res, mode, iteration, objective, ms, dog_max, stitch_gap_max.
std::vector<std::string> series_columns();
std::string series_rows(const CaseResult& r);

}  // namespace sdog
