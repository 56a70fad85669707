#include "solver/patches/patch_stepper.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <numeric>

#include "base/stopwatch.h"
#include "solver/sqp/blas_threads.h"

namespace sdog {

std::vector<PatchReport> step_patches(std::vector<std::unique_ptr<PatchStepper>>& patches, Dofs& x,
                                      bool last, const std::vector<char>* active) {
  const auto t0 = Clock::now();
  const size_t n = patches.size();
  std::vector<PatchReport> reports(n);
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return patches[a]->vertex_count() > patches[b]->vertex_count();
  });
  auto step = [&](size_t i) {
    if (active && !(*active)[i]) {
      reports[i].patch = static_cast<int>(i);
      reports[i].converged = true;
      return;
    }
    serial_openmp_regions();  // this may be a TBB worker, see blas_threads.h
    const auto start = Clock::now();
    reports[i] = patches[i]->step(x, last);
    reports[i].start_ms = ms_between(t0, start);
    reports[i].thread = tbb::this_task_arena::current_thread_index();
  };
  // One task per patch, each taking patches from the shared queue until it is empty: a thread
  // that joins late (busy elsewhere) finds the patches that are left, largest first. Each step
  // reads and writes only its own patch's vertices of x.
  std::atomic<size_t> next{0};
  tbb::parallel_for(size_t(0), n, [&](size_t) {
    for (size_t k; (k = next.fetch_add(1)) < n;) step(order[k]);
  });
  return reports;
}

}  // namespace sdog
