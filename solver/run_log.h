#pragma once
// The run log: one CSV row per iteration (header below), the same for every solver mode.
//   iteration, t, objective, bending, isometry, positions, edge_points, stitching, angles,
//   fold_bias, objective_final_targets, dog_max, dog_l2, stitch_gap_max, edge_strain_max,
//   sqp_steps, step_length, fold_retries, folded, iteration_ms, factor_ms, link,
//   factorizations, restoration_steps, mode
// Term columns are unweighted sums of squared residuals; `objective` is weighted with the weights
// of that iteration (an escalated fold bias included). Times are the only columns that may differ
// between two runs with the same inputs.
#include <ostream>
#include <string>
#include <vector>

#include "solver/run.h"

namespace sdog {

std::string run_csv_header();
std::string run_csv_row(const IterationReport& r);
/// Names of the columns that hold wall-clock times.
std::vector<std::string> run_csv_time_columns();

/// Collects the CSV text of a run.
class RunCsv : public RunObserver {
 public:
  RunCsv() : text_(run_csv_header()) {}
  void on_iteration(const IterationReport& r, const Dofs&) override { text_ += run_csv_row(r); }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

}  // namespace sdog
