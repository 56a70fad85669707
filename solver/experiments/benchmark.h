#pragma once
// The speed benchmark (`sdog bench`): the corners protocol on a pattern at a resolution with each
// mode, repeated in rounds (every mode once per round); per-iteration times over iterations 10-240
// (the thesis's window), medians of the repeats.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/dog_model.h"
#include "solver/run/run.h"
#include "solver/run/run_config.h"

namespace sdog {

struct BenchCase {
  std::string pattern;  ///< SVG path
  std::string res;      ///< "XxY"
  std::string mode;
};

struct BenchOptions {
  int iterations = 250;  ///< moving iterations of the protocol (hold: a fifth of that)
  int repeat = 3;
};

struct BenchResult {
  std::string pattern;  ///< file stem
  std::string res, mode;
  int vertices = 0, dof = 0;
  double median_ms = 0;   ///< median over repeats of the per-run median iteration time
  double ms_per_dof = 0;
  double sqp_steps = 0;   ///< mean per iteration
  double factor_ms = 0;   ///< mean factorisation + solve time per iteration (timed window)
  double factorizations = 0;  ///< mean per iteration
  double final_objective = 0;
  double dog_max = 0;     ///< at the last iteration
  double dog_max_over_run = 0;
  std::vector<double> run_medians;  ///< per repeat (round), in order
  /// The standard mode's median_ms on the same pattern and resolution over this one's, and the
  /// median of the rounds' own ratios (paired_speedup); empty when the standard was not run there.
  std::optional<double> speedup, speedup_paired;
};

/// The median (upper median for even sizes; 0 when empty).
double median(std::vector<double> values);

/// The median over rounds k of reference_ms[k] / ms[k] (each ratio of two runs made one shortly
/// after the other); empty unless both have the same, non-zero number of rounds.
std::optional<double> paired_speedup(const std::vector<double>& reference_ms, const std::vector<double>& ms);

/// Fills speedup and speedup_paired of `results` (one pattern and resolution) from its `standard`
/// result, if it has one.
void relate_bench_to_standard(std::vector<BenchResult>& results);

/// The thesis's timing of a run from its per-iteration times (iteration 1 first): the median over
/// iterations 10-240, which leaves out the first iterations (symbolic analysis, warm caches) and
/// the hold; over every iteration when the run has fewer than 10.
double median_iteration_ms(const std::vector<double>& iteration_ms);
/// True for the iterations inside that window.
bool in_timing_window(int iteration);

/// The model a case runs on: the pattern meshed at the case's resolution, with the coarse mesh
/// and the map when the mode needs them. Throws the library errors (UsageError for a resolution
/// the mode cannot use).
DogModel build_case_model(const BenchCase& c);

/// One run of `mode` over the configuration's scenario on the model's fine mesh, from the
/// scenario's start state, reported to the observers. Throws UsageError when the mode or the
/// scenario cannot run on this model; a diverging run returns with `failed` set.
RunSummary run_case(const DogModel& model, const std::string& mode, const RunConfig& config,
                    const std::vector<RunObserver*>& observers);

/// Called after every iteration of a benchmark run: the case, its repeat (0-based), the
/// iteration and the run's iteration count.
using BenchProgress = std::function<void(const BenchCase&, int repeat, int iteration, int total)>;

/// Runs `cases` (typically the modes of one pattern and resolution) `options.repeat` times each,
/// in rounds: every case once, in order, before the next round begins, so that the runs whose
/// times are compared are made close together on a machine whose load drifts. Results in the
/// order of `cases`. Throws SolverError when a run fails.
std::vector<BenchResult> run_benchmark_rounds(const std::vector<BenchCase>& cases, const BenchOptions& options,
                                              const BenchProgress& progress = {});

/// A number for a CSV field: printf's %g with `digits` significant digits; empty when absent.
std::string csv_number(double v, int digits);
std::string optional_csv_number(const std::optional<double>& v, int digits);

/// The CSV header and row of a result (columns: pattern, res, mode, vertices, dof, median_ms,
/// ms_per_dof, sqp_steps, factor_ms, final_objective, dog_max, factorizations, dog_max_over_run,
/// repeats, speedup, speedup_paired; the last two empty without a standard result).
std::string bench_csv_header();
std::string bench_csv_row(const BenchResult& r);

/// The 16 cases of the thesis (Table 6.1) for patterns in `dir`.
std::vector<BenchCase> thesis_grid(const std::string& dir, const std::string& mode);

}  // namespace sdog
