#include "solver/sqp/blas_threads.h"

#include <dlfcn.h>

#include <cstdlib>

namespace sdog {

int default_blas_threads() {
  if (const char* env = std::getenv("SDOG_BLAS_THREADS")) {
    const int n = std::atoi(env);
    if (n >= 1 && n <= 64) return n;
  }
  return 2;
}

// Both looked up at run time, once: CHOLMOD reaches the BLAS through Debian's libblas
// alternative, which may or may not be OpenBLAS, and OpenMP comes with CHOLMOD, not with this
// program.
using SetInt = void (*)(int);

void serial_openmp_regions() {
  static const auto levels =
      reinterpret_cast<SetInt>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
  // With no active levels allowed every parallel region runs on one thread (also regions with an
  // explicit num_threads clause, which OMP_NUM_THREADS cannot limit).
  if (levels) levels(0);
}

std::string blas_description() {
  using GetText = char* (*)();
  const auto config = reinterpret_cast<GetText>(dlsym(RTLD_DEFAULT, "openblas_get_config"));
  return config ? config() : "unknown (not OpenBLAS)";
}

bool set_blas_threads(int n) {
  static const auto threads =
      reinterpret_cast<SetInt>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  serial_openmp_regions();
  if (!threads) return false;
  threads(n);
  return true;
}

}  // namespace sdog
