#pragma once
// The run log: one CSV row per iteration (run_csv_columns(); docs/reference/output-files.md says
// what each column holds), the same for every solver mode. Term columns are unweighted sums of
// squared residuals; `objective` is weighted with the weights of that iteration (an escalated fold
// bias included). Times are the only columns that may differ between two runs with the same inputs.
#include <ostream>
#include <string>
#include <vector>

#include "solver/run/run.h"

namespace sdog {

std::vector<std::string> run_csv_columns();
std::string run_csv_header();
std::string run_csv_row(const IterationReport& r);
/// Names of the columns that hold wall-clock times.
std::vector<std::string> run_csv_time_columns();

/// The per-patch log of the multi-patch modes (patches.csv): one row per patch and iteration,
///   iteration, mode, patch, thread, start_ms, ms, linear_ms, steps, factorizations, objective,
///   dog_max, converged
/// (solver/patches/patch_report.h). `thread` is the TBB worker that ran the solve and `start_ms`
/// when it started, from the start of the patch round: together a timeline of thread use.
/// Iterations of a single-mesh mode have no rows. With the colour sweep an iteration has several
/// rounds: times and counts are summed over them, start and thread are those of the first.
std::vector<std::string> patches_csv_columns();
std::string patches_csv_header();
std::string patches_csv_rows(const IterationReport& r);

/// Collects the CSV text of a run.
class RunCsv : public RunObserver {
 public:
  RunCsv() : text_(run_csv_header()) {}
  void on_iteration(const IterationReport& r, const Dofs&) override { text_ += run_csv_row(r); }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

/// Collects patches.csv of a run; empty() while no iteration had patch solves.
class PatchesCsv : public RunObserver {
 public:
  PatchesCsv() : text_(patches_csv_header()) {}
  void on_iteration(const IterationReport& r, const Dofs&) override {
    text_ += patches_csv_rows(r);
  }
  bool empty() const { return text_.size() == patches_csv_header().size(); }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

}  // namespace sdog
