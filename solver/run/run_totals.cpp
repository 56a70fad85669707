#include "solver/run/run_totals.h"

#include <algorithm>

#include "base/statistics.h"

namespace sdog {

bool in_timing_window(int iteration) {
  return iteration >= 10 && iteration <= 240;
}

double median_iteration_ms(const std::vector<double>& iteration_ms) {
  std::vector<double> window;
  for (size_t k = 0; k < iteration_ms.size(); ++k)
    if (in_timing_window(static_cast<int>(k) + 1)) window.push_back(iteration_ms[k]);
  return median(window.empty() ? iteration_ms : window);
}

void RunTotals::on_iteration(const IterationReport& r, const Dofs&) {
  const double dog = r.diagnostics.dog_max;
  if (dog > dog_tolerance_) ++dog_misses;
  if (dog > worst_dog) worst_iteration = r.iteration;
  worst_dog = std::max(worst_dog, dog);
  work += r.step.work;
  if (in_timing_window(r.iteration)) {
    window_work += r.step.work;
    ++window_iterations;
  }
  iteration_ms.push_back(r.iteration_ms);
}

}  // namespace sdog
