// The signed fold angle reached at fold sites (crease_angles.h): FOLD's sign, valleys positive.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/dog_model.h"
#include "solver/problem/crease_angles.h"
#include "solver/run/run_setup.h"
#include "solver/terms/dihedral_angles.h"
#include "tests/geometry/pattern_builders.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

// The sheet of a straight crease at x = 45 (mesh x = 4.5), each side turned up (valley, theta > 0)
// or down (mountain) by theta about the crease: a fold of 2 theta.
Dofs folded(const DogModel& model, double theta) {
  const DogMesh& mesh = model.fine;
  Dofs x = to_dofs(mesh.V);
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const int p = mesh.vertex_patch[v];
    // The patch whose vertices include the sheet's left edge owns the left side.
    const bool left = mesh.V(mesh.patch_begin[p], 0) == 0;
    const double along = left ? 4.5 - mesh.V(v, 0) : mesh.V(v, 0) - 4.5;  // from the crease into the patch
    x[3 * v] = left ? 4.5 - along * std::cos(theta) : 4.5 + along * std::cos(theta);
    x[3 * v + 2] = along * std::sin(theta);
  }
  return x;
}

TEST(CreaseAngles, SignedFoldAngleOfAStraightCrease) {
  const DogModel model = build_dog_model(test::rectangle_pattern(100, 100, {{{45, 0}, {45, 100}}}), {11, 11});
  const FoldAngles angles(model.fine);
  ASSERT_GT(angles.sites().size(), 5u);
  for (size_t k = 0; k < angles.sites().size(); ++k) {
    EXPECT_NEAR(angles.at(k, to_dofs(model.fine.V)), 0, 1e-9);
    EXPECT_NEAR(angles.at(k, folded(model, M_PI / 6)), 60, 1e-9) << "valley";
    EXPECT_NEAR(angles.at(k, folded(model, -M_PI / 6)), -60, 1e-9) << "mountain";
    EXPECT_NEAR(angles.at(k, folded(model, 0.4 * M_PI)), 144, 1e-9);
  }
}

// The angle term (dihedral_angles.h) measures the same signed angle, and its residual vanishes at
// its target only: the mirror image of a fold and the supplement of an angle above 90 degrees are
// no minimum.
TEST(CreaseAngles, TheAngleTermTellsValleyFromMountainAndAnglesAbove90) {
  const DogModel model = build_dog_model(test::rectangle_pattern(100, 100, {{{45, 0}, {45, 100}}}), {11, 11});
  const auto sites = fold_sites(model.fine);
  ASSERT_GT(sites.size(), 5u);
  DihedralAngleTerm term;
  for (const auto& site : sites) term.add(dihedral_site(model.fine, site), M_PI / 3);
  auto residual_norm = [&](int b, const Dofs& x) {
    Eigen::Vector3d p[8];
    gather_block(term, b, x, p);
    double r[2];
    term.evaluate(b, p, r, nullptr);
    return std::hypot(r[0], r[1]);
  };
  for (int b = 0; b < term.block_count(); ++b) {
    Eigen::Vector3d p[8];
    for (double half : {M_PI / 12, -M_PI / 6, 0.4 * M_PI, -0.45 * M_PI}) {
      gather_block(term, b, folded(model, half), p);
      EXPECT_NEAR(term.measure(b, p), 2 * half, 1e-9) << "block " << b << ", fold " << 2 * half;
    }
    EXPECT_LT(residual_norm(b, folded(model, M_PI / 6)), 1e-12);
    EXPECT_GT(residual_norm(b, folded(model, -M_PI / 6)), 0.5);  // the mirror: sin^2(alpha) |e^{i60} - e^{-i60}|
    term.set_target(b, 0.8 * M_PI);  // 144 degrees, not its supplement 36
    EXPECT_LT(residual_norm(b, folded(model, 0.4 * M_PI)), 1e-12);
    EXPECT_GT(residual_norm(b, folded(model, 0.1 * M_PI)), 0.5);
    term.set_target(b, M_PI / 3);
  }
}

TEST(CreaseAngles, CurvedPleatsFoldAsDrawn) {
  // Alternating red mountains and blue valleys: every fold site reaches its assignment's sign.
  const DogModel model = build_dog_model(read_crease_pattern(test::dataset("curved_pleats.svg")), {41, 41});
  RunConfig config;
  config.scenario = ScenarioKind::kFold;
  config.fold_angle = 60;
  config.iterations = 40;
  config.hold = 20;
  RunSetup setup(model, ModeKind::kStandard, config);
  ASSERT_EQ(setup.run({}).termination, Termination::kCompleted);
  const FoldAngles angles(model.fine);
  ASSERT_GT(angles.sites().size(), 100u);
  for (size_t k = 0; k < angles.sites().size(); ++k) {
    const auto& curve = model.fine.stitching.curves[angles.sites()[k].curve];
    ASSERT_NE(curve.fold, Fold::kUnassigned);
    EXPECT_NEAR(angles.at(k, setup.positions()), 60 * fold_sign(curve.fold), 3) << "site " << k << " of " << curve.id;
  }
}

}  // namespace
}  // namespace sdog
