#pragma once
// The mode comparison (`sdog compare`): the protocol of `sdog bench` (run_case) for several modes
// on the same patterns and resolutions, one row per (pattern, resolution, mode) with the final
// state, timing and the ratios to the standard mode, and the per-iteration series for the plots.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solver/experiments/benchmark.h"
#include "solver/run/run_config.h"

namespace sdog {

/// One iteration of a compared run.
struct ComparePoint {
  int iteration = 0;
  double objective = 0;  ///< weighted, fine mesh
  double ms = 0;         ///< time of the iteration
  double dog_max = 0;
  double stitch_gap_max = 0;
};

enum class CompareStatus { Completed, Failed, Skipped };
/// "completed", "failed" (the solver stopped: diverged, failed factorisation), "skipped" (the mode
/// cannot run the case, e.g. an even resolution for a mode that needs the coarse mesh).
const char* to_string(CompareStatus s);

struct CompareRow {
  std::string pattern;  ///< file stem
  std::string res, mode;
  CompareStatus status = CompareStatus::Completed;
  std::string note;  ///< why a run failed or was skipped
  int vertices = 0, dof = 0;
  int iterations = 0;  ///< completed iterations (of the last repeat)
  double final_objective = 0;
  double median_ms = 0;  ///< median over the repeats of median_iteration_ms
  std::vector<double> round_ms;  ///< median_iteration_ms of each completed repeat, in order
  /// Median over the repeats of the whole run's time: the sum of every iteration's time, first
  /// and last included (a mode's start-up and its end, e.g. the two-level mode's standard finish).
  double total_s = 0;
  double dog_max = 0;    ///< at the end
  double dog_max_run = 0;  ///< worst over every iteration of every repeat
  double stitch_gap_max = 0;  ///< at the end
  bool folded = false;        ///< at the end
  /// final_objective / standard's, standard's median_ms / median_ms and standard's total_s /
  /// total_s, on the same pattern and resolution; empty when standard was not run there or either
  /// run did not complete.
  std::optional<double> objective_ratio, speedup, total_speedup;
  /// The median over the rounds (run_compare_rounds) of the standard's median_iteration_ms in the
  /// round over this mode's: each ratio is of two runs made one shortly after the other, so it
  /// is less moved by a load that drifts over the whole comparison than `speedup` is. Empty
  /// unless both rows completed every round.
  std::optional<double> speedup_paired;
  std::vector<ComparePoint> series;  ///< of the last repeat

  bool completed() const { return status == CompareStatus::Completed; }
  /// Time per iteration per degree of freedom (thesis Fig. 6.7).
  double ms_per_dof() const { return dof > 0 ? median_ms / dof : 0; }
};

/// The observers of one run: the case and its round (0-based).
using ObserversOfRun = std::function<std::vector<RunObserver*>(const BenchCase&, int round)>;

/// Runs `cases` (the modes of one pattern and resolution) `repeat` times each with the
/// configuration (scenario, iterations, hold, weights, solvers), in rounds: round k runs every
/// case once, in order, before round k + 1 begins, so that the runs that are compared are made
/// close together in time (side by side) on a machine whose load drifts. A mode that cannot run
/// its case (UsageError, SolverError from the model, the mode or the scenario) gives a Skipped row
/// and a diverging run a Failed row, both with the reason in `note` and no further runs; the other
/// cases go on. Other errors (an unreadable pattern) propagate. Rows in the order of `cases`;
/// `observers` gives the extra observers of each run.
std::vector<CompareRow> run_compare_rounds(const std::vector<BenchCase>& cases, const RunConfig& config, int repeat,
                                           const ObserversOfRun& observers = {});

/// Fills objective_ratio, speedup, total_speedup and speedup_paired of every row from the
/// completed `standard` row of its pattern and resolution.
void relate_to_standard(std::vector<CompareRow>& rows);

/// compare.csv: pattern, res, mode, vertices, dof, iterations, final_objective, objective_ratio,
/// median_ms, speedup, total_s, total_speedup, speedup_paired, dog_max, dog_max_run,
/// stitch_gap_max, folded, status, note. Empty fields for what a row does not have (ratios without standard, numbers of a
/// skipped run).
std::vector<std::string> compare_columns();
std::vector<std::string> compare_fields(const CompareRow& r);
/// series.csv (long format): pattern, res, mode, iteration, objective, ms, dog_max, stitch_gap_max.
std::string series_csv_header();
std::string series_csv_rows(const CompareRow& r);

/// A CSV line from fields (fields with a comma, quote or newline are quoted, RFC 4180).
std::string csv_line(const std::vector<std::string>& fields);

}  // namespace sdog
