#include "solver/blas_threads.h"

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

bool set_blas_threads(int n) {
  // Looked up at run time: CHOLMOD reaches the BLAS through Debian's libblas alternative, which
  // may or may not be OpenBLAS.
  using SetThreads = void (*)(int);
  auto f = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!f) return false;
  f(n);
  return true;
}

}  // namespace sdog
