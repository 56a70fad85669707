#include "app/blas_kernels.h"

#include <unistd.h>

#include <cstdlib>

namespace sdog {

void use_avx2_blas_kernels(char** argv) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (std::getenv("OPENBLAS_CORETYPE") != nullptr) return;
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) return;
  if (setenv("OPENBLAS_CORETYPE", "Haswell", 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only on failure: go on with the kernels loaded
#else
  (void)argv;
#endif
}

}  // namespace sdog
