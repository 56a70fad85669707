#include "solver/patch_stepper.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "solver/stopwatch.h"

namespace sdog {

std::vector<PatchReport> step_patches(std::vector<std::unique_ptr<PatchStepper>>& patches, Dofs& x, bool last,
                                      const std::vector<char>* active) {
  const auto t0 = Clock::now();
  std::vector<PatchReport> reports(patches.size());
  // Each step reads and writes only its own patch's vertices of x.
  tbb::parallel_for(size_t(0), patches.size(), [&](size_t i) {
    if (active && !(*active)[i]) {
      reports[i].patch = static_cast<int>(i);
      reports[i].converged = true;
      return;
    }
    const auto start = Clock::now();
    reports[i] = patches[i]->step(x, last);
    reports[i].start_ms = ms_between(t0, start);
    reports[i].thread = tbb::this_task_arena::current_thread_index();
  });
  return reports;
}

}  // namespace sdog
