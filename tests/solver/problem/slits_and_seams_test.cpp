// Slits and creases that end inside the sheet (crease_pattern.h), meshed and folded: a seam keeps
// the paper smooth beyond a crease's end, so the fold fades to flat there, and a slit's two sides
// part when the sheet is pulled apart across it, while everything stitched stays together.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "base/errors.h"
#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "geometry/pattern/fold_tips.h"
#include "solver/run/run_setup.h"
#include "solver/terms/dihedral_angles.h"
#include "solver/terms/fold_angles.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

DogModel model_of(const std::string& name, const Resolution& res) {
  return build_dog_model(read_crease_pattern(test::dataset(name)), res);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? NAN : v[v.size() / 2];
}

// The largest distance between the copies of crease point p in x.
double copy_gap(const DogMesh& mesh, const Dofs& x, int p) {
  const auto& copies = mesh.stitching.points[p].copies;
  const Eigen::MatrixX3d X = to_positions(x);
  double gap = 0;
  for (size_t a = 1; a < copies.size(); ++a)
    gap = std::max(gap, (DogMesh::position(X, copies[a]) - DogMesh::position(X, copies[0])).norm());
  return gap;
}

// The largest angle between the two sides' edges across the seams at their grid-vertex sites.
double largest_seam_vertex_angle(const DogMesh& mesh, const Dofs& x) {
  const Eigen::MatrixX3d X = to_positions(x);
  double largest = 0;
  for (const DihedralSite& d : seam_vertex_sites(mesh)) {
    const Eigen::Vector3d ea = X.row(d.vertices[0]) - X.row(d.vertices[1]);
    const Eigen::Vector3d eb = X.row(d.vertices[2]) - X.row(d.vertices[3]);
    largest =
        std::max(largest, std::acos(std::clamp(ea.normalized().dot(eb.normalized()), -1.0, 1.0)) *
                              180 / M_PI);
  }
  return largest;
}

TEST(SlitsAndSeams, ACreaseEndingInsideTheSheetFoldsAndItsFoldFadesToFlatAtTheEnd) {
  const DogModel model = model_of("crease_ending_inside.svg", {41, 27});
  const auto& curves = model.fine.stitching.curves;
  ASSERT_EQ(curves.size(), 3u);
  ASSERT_EQ(curves[2].kind, CurveKind::kSeam);
  ASSERT_EQ(model.fine.fold_tips.size(), 1u) << "the valley's end inside the sheet";
  RunConfig config;
  config.scenario = ScenarioKind::kFold;
  config.fold_angle = 60;
  config.iterations = 20;
  config.hold = 10;
  RunSetup setup(model, ModeKind::kStandard, config);
  ASSERT_EQ(setup.run({}).termination, Termination::kCompleted);
  const Dofs x = setup.positions();
  const FoldAngles angles(model.fine);
  const Eigen::Vector2d tip = model.fine.fold_tips[0];
  std::vector<double> far_valley, seam;
  double nearest_distance = INFINITY, nearest_angle = NAN;
  for (size_t k = 0; k < angles.sites().size(); ++k) {
    const FoldSite& site = angles.sites()[k];
    const double a = angles.at(k, x);
    const double d = (model.fine.stitching.points[site.point].flat - tip).norm();
    if (site.curve == 1) EXPECT_LT(a, -20) << "the mountain folds as drawn, site " << k;
    if (site.curve == 2) seam.push_back(std::abs(a));
    if (site.curve == 0 && d > kFoldTipRadius) far_valley.push_back(a);
    if (site.curve == 0 && d < nearest_distance) nearest_distance = d, nearest_angle = a;
  }
  ASSERT_GE(far_valley.size(), 5u);
  ASSERT_GE(seam.size(), 5u);
  EXPECT_GT(*std::min_element(far_valley.begin(), far_valley.end()), 20)
      << "the valley folds as drawn away from its end";
  EXPECT_LT(*std::max_element(seam.begin(), seam.end()), 3) << "the seam stays smooth";
  EXPECT_LT(std::abs(nearest_angle), 0.5 * median(far_valley))
      << "the fold fades towards the end (the valley's site " << nearest_distance
      << " grid edges from it)";
}

TEST(SlitsAndSeams, ASlitsSidesPartWhenPulledWhileTheSeamsAndCreasesStayStitched) {
  const DogModel model = model_of("slits_and_tab.svg", {41, 45});
  EXPECT_EQ(model.fine.patch_count(), 4);
  const CreaseStitching& st = model.fine.stitching;
  // Crease points on slits only have no stitching pair; every other one has.
  std::vector<int> on_slit(st.points.size(), 0), elsewhere(st.points.size(), 0);
  for (const auto& curve : st.curves)
    for (int p : curve.points) (curve.kind == CurveKind::kSlit ? on_slit : elsewhere)[p] = 1;
  std::vector<int> pairs(st.points.size(), 0);
  for (const auto& pair : st.pairs) ++pairs[pair.point];
  int slit_only = 0;
  for (size_t p = 0; p < st.points.size(); ++p) {
    if (on_slit[p] && !elsewhere[p]) {
      ++slit_only;
      EXPECT_EQ(pairs[p], 0) << p;
    } else {
      EXPECT_EQ(pairs[p], static_cast<int>(st.points[p].copies.size()) - 1) << p;
    }
  }
  EXPECT_GE(slit_only, 20);
  // Pull the sheet apart across the edge slit (at x = 75, from the bottom edge y = -100 up to
  // y = -62): hold a vertex left of it, lift one right of it.
  RunConfig config;
  config.scenario = ScenarioKind::kNone;
  config.iterations = 10;
  config.hold = 10;
  PositionSpec hold, lift;
  hold.path = "hold";
  hold.near = Eigen::Vector2d(64, -100);
  hold.move = Eigen::Vector3d::Zero();
  lift.path = "lift";
  lift.near = Eigen::Vector2d(86, -100);
  lift.move = Eigen::Vector3d(0, 0, 8);
  config.positions = {hold, lift};
  RunSetup setup(model, ModeKind::kStandard, config);
  ASSERT_EQ(setup.run({}).termination, Termination::kCompleted);
  const Dofs x = setup.positions();
  double slit_gap = 0, stitched_gap = 0;
  for (size_t p = 0; p < st.points.size(); ++p)
    (on_slit[p] && !elsewhere[p] ? slit_gap : stitched_gap) =
        std::max(on_slit[p] && !elsewhere[p] ? slit_gap : stitched_gap,
                 copy_gap(model.fine, x, static_cast<int>(p)));
  EXPECT_GT(slit_gap, 3) << "the slit opens";
  EXPECT_LT(stitched_gap, 1e-2) << "seams and creases hold";
  // The seams run along grid lines (x = 75 and y = -25 are grid lines at 41x45): their sites are
  // on grid vertices.
  EXPECT_GE(seam_vertex_sites(model.fine).size(), 30u);
  EXPECT_LT(largest_seam_vertex_angle(model.fine, x), 2) << "the seams stay smooth";
}

TEST(SlitsAndSeams, ASeamAlongAGridLineBendsSmoothlyWhereACreaseWouldHinge) {
  // Lift the strip above the inner slit's seams (y > -25): a crease there would be a free hinge;
  // the seam bends with the paper.
  const DogModel model = model_of("slits_and_tab.svg", {41, 45});
  RunConfig config;
  config.scenario = ScenarioKind::kNone;
  config.iterations = 10;
  config.hold = 10;
  std::vector<PositionSpec> specs;
  for (const auto& [p, dz] : {std::pair{Eigen::Vector2d(10, -60), 0.0},
                              {{90, -60}, 0.0},
                              {{10, -40}, 0.0},
                              {{90, -40}, 0.0},
                              {{0, 0}, 10.0},
                              {{100, 0}, 10.0}}) {
    PositionSpec spec;
    spec.path = "drag";
    spec.near = p;
    spec.move = Eigen::Vector3d(0, 0, dz);
    specs.push_back(spec);
  }
  config.positions = specs;
  RunSetup setup(model, ModeKind::kStandard, config);
  ASSERT_EQ(setup.run({}).termination, Termination::kCompleted);
  // 0.4 degrees; without the seams' angle targets the strip hinges along them by 5.5 degrees.
  EXPECT_LT(largest_seam_vertex_angle(model.fine, setup.positions()), 2);
}

TEST(SlitsAndSeams, ModesThatTakeACreasePointAsOnePointRefuseSlits) {
  const DogModel model = model_of("slits_and_tab.svg", {41, 45});
  RunConfig config;
  config.scenario = ScenarioKind::kFold;
  for (ModeKind mode : {ModeKind::kCoarse, ModeKind::kSubsolvers}) {
    try {
      RunSetup setup(model, mode, config);
      FAIL() << enum_name(mode) << " accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("would close the pattern's slits"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace sdog
