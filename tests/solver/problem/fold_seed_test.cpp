// The fold seed of a start state (fold_seed.h): valleys tilt up, mountains down.
#include <gtest/gtest.h>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/problem/fold_seed.h"
#include "solver/terms/crease_geometry.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

TEST(FoldSeed, ValleyTiltsUpAndMountainDown) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {21, 15});
  const std::vector<bool> inside = inside_own_patch(model.fine);
  const Dofs flat = to_dofs(model.fine.V);
  const Dofs valley = fold_seed(model.fine, {1.0});
  const Dofs mountain = fold_seed(model.fine, {-1.0});
  int raised = 0;
  for (int v = 0; v < model.fine.vertex_count(); ++v) {
    EXPECT_EQ(valley[3 * v], flat[3 * v]);
    EXPECT_EQ(valley[3 * v + 1], flat[3 * v + 1]);
    EXPECT_EQ(mountain[3 * v + 2], -valley[3 * v + 2]);
    if (inside[v]) {
      EXPECT_GE(valley[3 * v + 2], 0) << "vertex " << v;
    } else {
      EXPECT_LE(valley[3 * v + 2], 0) << "vertex " << v;
    }
    raised += valley[3 * v + 2] > 1e-4;
  }
  EXPECT_GT(raised, model.fine.vertex_count() / 2);
  // No sign for the curve: the flat state.
  EXPECT_TRUE(fold_seed(model.fine, {0.0}) == flat);
}

}  // namespace
}  // namespace sdog
