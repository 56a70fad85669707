// step_patches (solver/patch_stepper.h): reports in patch order, the largest patch started first.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <mutex>
#include <vector>

#include "solver/patches/patch_stepper.h"
#include "tests/solver/probe_patch.h"

namespace sdog {
namespace {

TEST(StepPatches, LargestPatchesStartFirstAndReportsKeepPatchOrder) {
  std::mutex mutex;
  std::vector<int> order;
  const std::vector<int> sizes = {30, 900, 10, 500, 30};
  std::vector<std::unique_ptr<PatchStepper>> patches;
  for (int i = 0; i < static_cast<int>(sizes.size()); ++i)
    patches.push_back(std::make_unique<test::ProbePatch>(i, sizes[i], [&](int patch) {
      std::lock_guard<std::mutex> lock(mutex);
      order.push_back(patch);
    }));
  Dofs x = Dofs::Zero(3);
  std::vector<PatchReport> reports;
  tbb::task_arena one(1);  // one thread: the queue order is the step order
  one.execute([&] { reports = step_patches(patches, x, false); });
  EXPECT_EQ(order, (std::vector<int>{1, 3, 0, 4, 2}));  // by size, ties in patch order
  ASSERT_EQ(reports.size(), sizes.size());
  for (size_t i = 0; i < reports.size(); ++i) EXPECT_EQ(reports[i].patch, static_cast<int>(i));
}

}  // namespace
}  // namespace sdog
