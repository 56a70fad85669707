// The strain of the diagnostics: zero for a fold that bends the sheet without stretching it; for a
// patch stretched or shrunk by hand, the signed strain and patch of the worst edge of the paper,
// and the strain of every edge, the parts of cells beyond the crease included.
#include <gtest/gtest.h>

#include "geometry/mesh/dog_model.h"
#include "solver/problem/diagnostics.h"
#include "solver/run/run_setup.h"
#include "tests/geometry/pattern_builders.h"

namespace sdog {
namespace {

// The sheet of a straight crease at mesh x = 4.5, its right side turned up by `theta` about the
// crease (a rigid fold) and its x coordinates scaled by `scale` about the crease.
Dofs right_side(const DogModel& model, int right, double theta, double scale) {
  const DogMesh& mesh = model.fine;
  Dofs x = to_dofs(mesh.V);
  for (int v = mesh.patch_begin[right]; v < mesh.patch_begin[right + 1]; ++v) {
    const double along = scale * (mesh.V(v, 0) - 4.5);
    x[3 * v] = 4.5 + along * std::cos(theta);
    x[3 * v + 2] = along * std::sin(theta);
  }
  return x;
}

TEST(EdgeStrain, NamesTheWorstEdgeItsSignAndItsPatch) {
  const DogModel model =
      build_dog_model(test::rectangle_pattern(100, 100, {{{45, 0}, {45, 100}}}), {11, 11});
  const DogMesh& mesh = model.fine;
  ASSERT_EQ(mesh.patch_count(), 2);
  const int right = mesh.V(mesh.patch_begin[0], 0) == 0 ? 1 : 0;
  RunConfig config;
  RunSetup setup(model, ModeKind::kStandard, config);
  const DogProblem& problem = setup.problem();

  // Paper: the grid edges between vertices on the crease's side of their patch (x = 0..4 on the
  // left, 5..10 on the right), none across it: 4 x 11 + 5 x 10 on the left, 5 x 11 + 6 x 10 on
  // the right.
  int paper = 0;
  for (char e : problem.sheet_edges) paper += e;
  EXPECT_EQ(paper, 94 + 115);

  const Diagnostics folded = diagnose(problem, right_side(model, right, 1.0, 1.0));
  EXPECT_LT(folded.edge_strain_max, 1e-12);
  EXPECT_LT(folded.sheet_strain_max, 1e-12);

  // Every edge of the right patch along x is 1.2 (0.7) times its rest length; the others keep
  // theirs.
  const Diagnostics longer = diagnose(problem, right_side(model, right, 0.5, 1.2));
  EXPECT_NEAR(longer.sheet_strain_max, 0.2, 1e-12);
  EXPECT_NEAR(longer.edge_strain_max, 0.2, 1e-12);
  EXPECT_NEAR(longer.sheet_strain_worst, 0.2, 1e-12);
  EXPECT_EQ(longer.sheet_strain_patch, right);
  EXPECT_GT(longer.sheet_strain_max, kStretchedStrain);

  // Only the vertices beyond the crease moved further out: the paper keeps its lengths.
  Dofs beyond = right_side(model, right, 0.0, 1.0);
  int moved = 0;
  for (int v = mesh.patch_begin[right]; v < mesh.patch_begin[right + 1]; ++v)
    if (mesh.V(v, 0) < 4.5) {
      beyond[3 * v] -= 0.5;
      ++moved;
    }
  ASSERT_GT(moved, 0);
  const Diagnostics ghost = diagnose(problem, beyond);
  EXPECT_NEAR(ghost.edge_strain_max, 0.5, 1e-9);  // grid edges of 1 mesh unit
  EXPECT_LT(ghost.sheet_strain_max, 1e-12);

  const Diagnostics shorter = diagnose(problem, right_side(model, right, 0.5, 0.7));
  EXPECT_NEAR(shorter.sheet_strain_max, 0.3, 1e-12);
  EXPECT_NEAR(shorter.sheet_strain_worst, -0.3, 1e-12);
  EXPECT_EQ(shorter.sheet_strain_patch, right);
}

}  // namespace
}  // namespace sdog
