#pragma once
// Totals over the iterations of a run, collected as an observer: the work, the times, the worst DOG
// residual, and the thesis's timing window (iterations 10-240, which leaves out the first
// iterations (symbolic analysis, warm caches) and the hold).
#include <vector>

#include "solver/run/run.h"

namespace sdog {

/// True for the iterations inside the timing window.
bool in_timing_window(int iteration);
/// The median over the timing window of per-iteration times (iteration 1 first); over every
/// iteration when the run has fewer than 10.
double median_iteration_ms(const std::vector<double>& iteration_ms);

class RunTotals : public RunObserver {
 public:
  /// `dog_tolerance`: iterations whose DOG residual ends above it are counted.
  explicit RunTotals(double dog_tolerance = 0) : dog_tolerance_(dog_tolerance) {}
  void on_iteration(const IterationReport& r, const Dofs& x) override;

  Work work;         ///< of every iteration
  Work window_work;  ///< of the iterations in the timing window
  int window_iterations = 0;
  std::vector<double> iteration_ms;
  double worst_dog = 0;  ///< largest DOG residual after any iteration
  int worst_iteration = 0;
  int dog_misses = 0;  ///< iterations that ended above the DOG tolerance
  /// median_iteration_ms of the run.
  double median_window_ms() const { return median_iteration_ms(iteration_ms); }

 private:
  double dog_tolerance_;
};

}  // namespace sdog
