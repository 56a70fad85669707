#include "app/threads.h"

#include <tbb/global_control.h>

#include <memory>
#include <thread>

#include "solver/sqp/blas_threads.h"

namespace sdog::cli {

void set_thread_count(int n) {
  if (n <= 0) n = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  static std::unique_ptr<tbb::global_control> control;
  control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, n);
  set_blas_threads(default_blas_threads());  // fixed, see blas_threads.h
}

}  // namespace sdog::cli
