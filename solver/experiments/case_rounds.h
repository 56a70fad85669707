#pragma once
// The experiments of `sdog bench` and `sdog compare`: cases (a pattern at a resolution with a
// mode) run over the configuration's scenario, repeated in rounds (every case once per round, so
// that the runs whose times are compared are made close together on a machine whose load drifts),
// and measured against the standard mode on the same pattern and resolution.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/enum_names.h"
#include "geometry/mesh/dog_model.h"
#include "solver/run/run.h"
#include "solver/run/run_config.h"

namespace sdog {

/// One case: a crease pattern (SVG path) at a resolution ("XxY") with a mode.
struct Case {
  std::string pattern;
  std::string res;
  ModeKind mode = ModeKind::kStandard;
};

/// One iteration of a case's run (the last round's), for the plots.
struct SeriesPoint {
  int iteration = 0;
  double objective = 0;  ///< weighted, fine mesh
  double ms = 0;         ///< time of the iteration
  double dog_max = 0;
  double stitch_gap_max = 0;
};

/// "completed", "failed" (the solver stopped: diverged, failed factorisation), "skipped" (the mode
/// cannot run the case, e.g. an even resolution for a mode that needs the coarse mesh).
enum class CaseStatus { kCompleted, kFailed, kSkipped };
template <>
struct EnumNames<CaseStatus> {
  static constexpr const char* noun = "case status";
  static constexpr EnumName<CaseStatus> rows[] = {
      {CaseStatus::kCompleted, "completed"},
      {CaseStatus::kFailed, "failed"},
      {CaseStatus::kSkipped, "skipped"},
  };
};

/// What the runs of a case measured.
struct CaseResult {
  std::string pattern;  ///< file stem
  std::string res;
  ModeKind mode = ModeKind::kStandard;
  CaseStatus status = CaseStatus::kCompleted;
  std::string note;  ///< why a run failed or was skipped
  int vertices = 0, dof = 0;
  int iterations = 0;            ///< completed iterations (of the last round)
  double final_objective = 0;    ///< at the end of the last round
  double dog_max = 0;            ///< at the end
  double stitch_gap_max = 0;     ///< at the end
  bool folded = false;           ///< at the end
  double dog_max_run = 0;        ///< worst after any iteration of any round
  std::vector<double> round_ms;  ///< median_iteration_ms of each completed round, in order
  double median_ms = 0;          ///< median of round_ms
  /// Median over the rounds of the whole run's time: the sum of every iteration's time, first and
  /// last included (a mode's start-up and its end, e.g. the two-level mode's standard finish).
  double total_s = 0;
  std::vector<double> round_total_s;
  Work window_work;  ///< summed over the timing windows of every round
  int window_iterations = 0;
  std::vector<SeriesPoint> series;  ///< of the last round
  /// final_objective / standard's, standard's median_ms / median_ms, standard's total_s / total_s
  /// and the median over the rounds of standard's round_ms / round_ms (each ratio of two runs made
  /// one shortly after the other); empty unless both completed (speedup_paired: every round).
  std::optional<double> objective_ratio, speedup, total_speedup, speedup_paired;

  bool completed() const { return status == CaseStatus::kCompleted; }
  /// Time per iteration per degree of freedom (thesis Fig. 6.7).
  double ms_per_dof() const { return dof > 0 ? median_ms / dof : 0; }
  /// Work per iteration in the timing windows.
  double per_window_iteration(double total) const {
    return window_iterations > 0 ? total / window_iterations : 0;
  }
};

/// The observers of one run: the case and its round (0-based).
using ObserversOfRun = std::function<std::vector<RunObserver*>(const Case&, int round)>;

struct RoundsOptions {
  int repeat = 1;
  /// true: a case that cannot run (UsageError or SolverError while setting it up) is recorded as
  /// skipped and a failing run as failed, and the other cases go on (`sdog compare`); false: they
  /// throw (`sdog bench`).
  bool record_problems = true;
  ObserversOfRun observers;
};

/// The model a case runs on: the pattern meshed at the case's resolution, with the coarse mesh
/// and the map when the mode needs them. Throws the library errors (UsageError for a resolution
/// the mode cannot use).
DogModel build_case_model(const Case& c);

/// Runs `cases` (the modes of one pattern and resolution) options.repeat times each in rounds:
/// round k runs every case once, in order, before round k + 1 begins. A case that stopped (skipped
/// or failed) runs no more. Results in the order of `cases`, related to the standard case among
/// them (relate_to_standard). Other errors (an unreadable pattern) propagate.
std::vector<CaseResult> run_rounds(const std::vector<Case>& cases, const RunConfig& config,
                                   const RoundsOptions& options);

/// Fills the ratios of every result from the completed standard result of its pattern and
/// resolution.
void relate_to_standard(std::vector<CaseResult>& results);

/// The 16 cases of the thesis (Table 6.1), patterns read from `dir`, each with `mode`.
std::vector<Case> thesis_grid(const std::string& dir, ModeKind mode = ModeKind::kStandard);

}  // namespace sdog
