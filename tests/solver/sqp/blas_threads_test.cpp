// The thread settings of the linear algebra under CHOLMOD (solver/blas_threads.h).
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <chrono>
#include <mutex>
#include <set>
#include <thread>

#include "solver/patches/patch_stepper.h"
#include "solver/sqp/blas_threads.h"
#include "tests/solver/probe_patch.h"

namespace sdog {
namespace {

using GetInt = int (*)();
using SetInt = void (*)(int);

TEST(BlasThreads, OpenMpRegionsRunOnTheCallingThread) {
  // CHOLMOD brings OpenMP along; its regions ask for 4 threads explicitly, which only a zero
  // active-level limit keeps on the calling thread.
  auto get_levels = reinterpret_cast<GetInt>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
  auto set_levels = reinterpret_cast<SetInt>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
  if (!get_levels || !set_levels)
    GTEST_SKIP() << "no OpenMP runtime loaded (CHOLMOD built without OpenMP)";
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

TEST(BlasThreads, PatchStepsRunOpenMpRegionsOnTheirOwnThread) {
  // libgomp keeps the limit per thread: a TBB worker that factorises a patch must set it itself,
  // or its factorisations start teams of 4 OpenMP threads that spin beside the other patches.
  auto get_levels = reinterpret_cast<GetInt>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
  if (!get_levels) GTEST_SKIP() << "no OpenMP runtime loaded (CHOLMOD built without OpenMP)";
  std::mutex mutex;
  std::set<int> levels, threads;
  std::vector<std::unique_ptr<PatchStepper>> patches;
  for (int i = 0; i < 8; ++i)
    patches.push_back(std::make_unique<test::ProbePatch>(i, 1, [&](int) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));  // gives the other worker a turn
      std::lock_guard<std::mutex> lock(mutex);
      levels.insert(get_levels());
      threads.insert(tbb::this_task_arena::current_thread_index());
    }));
  Dofs x = Dofs::Zero(3);
  tbb::task_arena arena(2);
  arena.execute([&] { step_patches(patches, x, false); });
  ASSERT_GE(threads.size(), 2u)
      << "the patches did not run on two threads, so this test checks nothing";
  EXPECT_EQ(levels, std::set<int>{0});
}

}  // namespace
}  // namespace sdog
