// The thread settings of the linear algebra under CHOLMOD (solver/blas_threads.h).
#include <dlfcn.h>
#include <gtest/gtest.h>

#include "solver/blas_threads.h"

namespace sdog {
namespace {

using GetInt = int (*)();
using SetInt = void (*)(int);

TEST(BlasThreads, OpenMpRegionsRunOnTheCallingThread) {
  // CHOLMOD brings OpenMP along; its regions ask for 4 threads explicitly, which only a zero
  // active-level limit keeps on the calling thread.
  auto get_levels = reinterpret_cast<GetInt>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
  auto set_levels = reinterpret_cast<SetInt>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
  if (!get_levels || !set_levels) GTEST_SKIP() << "no OpenMP runtime loaded (CHOLMOD built without OpenMP)";
  set_levels(4);
  ASSERT_EQ(get_levels(), 4);
  set_blas_threads(2);
  EXPECT_EQ(get_levels(), 0);
}

TEST(BlasThreads, OpenBlasTakesTheCount) {
  auto get_threads = reinterpret_cast<GetInt>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  if (!get_threads) GTEST_SKIP() << "the BLAS loaded is not OpenBLAS";
  ASSERT_TRUE(set_blas_threads(1));
  EXPECT_EQ(get_threads(), 1);
  ASSERT_TRUE(set_blas_threads(2));
  EXPECT_EQ(get_threads(), 2);
}

}  // namespace
}  // namespace sdog
