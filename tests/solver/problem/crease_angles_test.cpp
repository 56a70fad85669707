// The signed fold angle reached at fold sites (crease_angles.h): FOLD's sign, valleys positive.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "geometry/pattern/fold_tips.h"
#include "solver/problem/crease_angles.h"
#include "solver/problem/diagnostics.h"
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
    const double along =
        left ? 4.5 - mesh.V(v, 0) : mesh.V(v, 0) - 4.5;  // from the crease into the patch
    x[3 * v] = left ? 4.5 - along * std::cos(theta) : 4.5 + along * std::cos(theta);
    x[3 * v + 2] = along * std::sin(theta);
  }
  return x;
}

// The fold scenario to `angle` degrees over `iterations`, then `hold` held iterations.
RunConfig fold_config(double angle, int iterations, int hold) {
  RunConfig config;
  config.scenario = ScenarioKind::kFold;
  config.fold_angle = angle;
  config.iterations = iterations;
  config.hold = hold;
  return config;
}

TEST(CreaseAngles, SignedFoldAngleOfAStraightCrease) {
  const DogModel model =
      build_dog_model(test::rectangle_pattern(100, 100, {{{45, 0}, {45, 100}}}), {11, 11});
  const FoldAngles angles(model.fine);
  ASSERT_GT(angles.sites().size(), 5u);
  for (size_t k = 0; k < angles.sites().size(); ++k) {
    EXPECT_NEAR(angles.at(k, to_dofs(model.fine.V)), 0, 1e-9);
    EXPECT_NEAR(angles.at(k, folded(model, M_PI / 6)), 60, 1e-9) << "valley";
    EXPECT_NEAR(angles.at(k, folded(model, -M_PI / 6)), -60, 1e-9) << "mountain";
    EXPECT_NEAR(angles.at(k, folded(model, 0.4 * M_PI)), 144, 1e-9);
  }
}

// creases.csv: a header and one row per fold site, with the site's crease, assignment, place,
// target and the angle reached (60 degrees on the valley folded by 2 x 30 degrees).
TEST(CreaseAngles, CreasesCsvHasOneRowPerFoldSite) {
  const DogModel model =
      build_dog_model(test::rectangle_pattern(100, 100, {{{45, 0}, {45, 100}}}), {11, 11});
  const FoldAngles angles(model.fine);
  const std::string csv =
      creases_csv(model.fine, fold_scenario(model.fine, 75), folded(model, M_PI / 6));
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "crease_point,crease,id,assignment,x,y,target_angle,angle");
  size_t rows = 0;
  while (std::getline(in, line)) {
    ASSERT_FALSE(line.empty()) << "blank line after row " << rows;
    const size_t last_comma = line.rfind(',');
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 7) << line;
    EXPECT_NE(line.find(",unassigned,4.5,"), std::string::npos) << line;
    EXPECT_NE(line.find(",75,"), std::string::npos) << line;
    EXPECT_NEAR(std::stod(line.substr(last_comma + 1)), 60, 1e-4) << line;
    ++rows;
  }
  EXPECT_EQ(rows, angles.sites().size());
  EXPECT_GT(rows, 5u);
}

// The angle term (dihedral_angles.h) measures the same signed angle, and its residual vanishes at
// its target only: the mirror image of a fold and the supplement of an angle above 90 degrees are
// no minimum.
TEST(CreaseAngles, TheAngleTermTellsValleyFromMountainAndAnglesAbove90) {
  const DogModel model =
      build_dog_model(test::rectangle_pattern(100, 100, {{{45, 0}, {45, 100}}}), {11, 11});
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
    EXPECT_GT(residual_norm(b, folded(model, -M_PI / 6)),
              0.5);                  // the mirror: sin^2(alpha) |e^{i60} - e^{-i60}|
    term.set_target(b, 0.8 * M_PI);  // 144 degrees, not its supplement 36
    EXPECT_LT(residual_norm(b, folded(model, 0.4 * M_PI)), 1e-12);
    EXPECT_GT(residual_norm(b, folded(model, 0.1 * M_PI)), 0.5);
    term.set_target(b, M_PI / 3);
  }
}

// Every fold site of every dataset reads 0 on the flat sheet. A crease that ends at a grid vertex
// of the boundary leaves a sliver of a cell between the curve and the edge at its last fold
// sites; the sliver's side of the crease comes from the stretch of edge it holds.
TEST(CreaseAngles, EveryFoldSiteReadsFlatAtRest) {
  int sites = 0;
  for (const auto& path : test::all_datasets()) {
    for (const Resolution res : {Resolution{21, 21}, Resolution{41, 41}, Resolution{31, 23}}) {
      const DogModel model = build_dog_model(read_crease_pattern(path), res);
      const FoldAngles angles(model.fine);
      const Dofs rest = to_dofs(model.fine.V);
      for (size_t k = 0; k < angles.sites().size(); ++k, ++sites)
        EXPECT_NEAR(angles.at(k, rest), 0, 1e-4) << path << " " << res.str() << " site " << k;
    }
  }
  EXPECT_GT(sites, 5000);
}

// Both directions of the corner arcs (three unassigned arcs, one valley) fold every site the
// asked way, the crease ends in slivers at the sheet's corners included.
TEST(CreaseAngles, CornerArcsFoldBothWaysToTheirEnds) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {21, 21});
  for (const double angle : {60.0, -60.0}) {
    RunSetup setup(model, ModeKind::kStandard, fold_config(angle, 60, 20));
    ASSERT_EQ(setup.run({}).termination, Termination::kCompleted);
    const FoldAngles angles(model.fine);
    ASSERT_EQ(angles.sites().size(), 48u);
    for (size_t k = 0; k < angles.sites().size(); ++k) {
      // An assigned crease folds its own way; the others the way the angle's sign says.
      const Fold fold = model.fine.stitching.curves[angles.sites()[k].curve].fold;
      const double target = fold == Fold::kUnassigned ? angle : std::abs(angle) * fold_sign(fold);
      EXPECT_NEAR(angles.at(k, setup.positions()), target, 10) << "site " << k << " at " << angle;
    }
  }
}

TEST(CreaseAngles, CurvedPleatsFoldAsDrawn) {
  // Alternating red mountains and blue valleys: every fold site reaches its assignment's sign.
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("curved_pleats.svg")), {41, 41});
  RunSetup setup(model, ModeKind::kStandard, fold_config(60, 40, 20));
  ASSERT_EQ(setup.run({}).termination, Termination::kCompleted);
  const FoldAngles angles(model.fine);
  ASSERT_GT(angles.sites().size(), 100u);
  for (size_t k = 0; k < angles.sites().size(); ++k) {
    const auto& curve = model.fine.stitching.curves[angles.sites()[k].curve];
    ASSERT_NE(curve.fold, Fold::kUnassigned);
    EXPECT_NEAR(angles.at(k, setup.positions()), 60 * fold_sign(curve.fold), 3)
        << "site " << k << " of " << curve.id;
  }
}

// The v pleat's two creases end together inside the sheet (a fold tip, where folds fade): the fold
// sites within kFoldTipRadius of it are counted apart from the others, and every site is counted
// once.
TEST(CreaseAngles, SitesNextToAFoldTipAreCountedApart) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("v_pleat.fold")), {21, 21});
  ASSERT_EQ(model.fine.fold_tips.size(), 1u);
  RunSetup setup(model, ModeKind::kStandard, fold_config(60, 10, 10));
  ASSERT_EQ(setup.run({}).termination, Termination::kCompleted);
  const AngleAgreement a = angle_agreement(setup.problem(), setup.positions());
  const FoldAngles angles(model.fine);
  // The tip is the FOLD vertex (50, 38) of a 100-unit sheet on 20 grid edges, y pointing down in
  // the FOLD file and up in the mesh: (10, 12.4).
  int near = 0, against_near = 0;
  for (size_t k = 0; k < angles.sites().size(); ++k) {
    const Eigen::Vector2d flat = model.fine.stitching.points[angles.sites()[k].point].flat;
    if (std::hypot(flat.x() - 10, flat.y() - 12.4) > kFoldTipRadius) continue;
    ++near;
    const auto& curve = model.fine.stitching.curves[angles.sites()[k].curve];
    const double angle = angles.at(k, setup.positions());
    if (std::abs(angle) > kBentDegrees && angle * fold_sign(curve.fold) < 0) ++against_near;
  }
  EXPECT_GT(near, 0);
  EXPECT_EQ(a.tip_sites, near);
  EXPECT_EQ(a.tip_against, against_near);
  EXPECT_EQ(a.tip_sites + a.targeted_sites, static_cast<int>(angles.sites().size()));
}

}  // namespace
}  // namespace sdog
