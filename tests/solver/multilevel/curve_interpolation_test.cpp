// The coarse-to-fine crease interpolation of the coarse mode (curve_interpolation.h).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/multilevel/curve_interpolation.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

// Largest distance between the fine crease points at rest and their interpolation from the
// coarse rest state, and the same for the chord (linear) interpolation of the map's fractions.
struct Errors {
  double cubic = 0, chord = 0;
  int points = 0;
};

Errors rest_errors(const DogModel& model) {
  const auto stencils = coarse_curve_stencils(model);
  Errors e;
  for (size_t c = 0; c < model.map.curves.size(); ++c) {
    const auto& coarse_points = model.coarse.stitching.curves[c].points;
    const int n = static_cast<int>(coarse_points.size());
    EXPECT_EQ(stencils[c].size(), model.map.curves[c].size());
    for (size_t k = 0; k < stencils[c].size(); ++k) {
      const Eigen::Vector3d fine =
          crease_point_mean(model.fine, model.fine.V, model.fine.stitching.curves[c].points[k]);
      const auto& cp = model.map.curves[c][k];
      const Eigen::Vector3d chord =
          cp.coarse >= 0
              ? crease_point_mean(model.coarse, model.coarse.V, coarse_points[cp.coarse])
              : Eigen::Vector3d(
                    (1 - cp.fraction) *
                        crease_point_mean(model.coarse, model.coarse.V, coarse_points[cp.segment]) +
                    cp.fraction * crease_point_mean(model.coarse, model.coarse.V,
                                                    coarse_points[(cp.segment + 1) % n]));
      double sum = 0;
      for (int i = 0; i < stencils[c][k].count; ++i) sum += stencils[c][k].weights[i];
      EXPECT_NEAR(sum, 1.0, 1e-12);
      e.cubic = std::max(e.cubic,
                         (interpolate(model.coarse, model.coarse.V, stencils[c][k]) - fine).norm());
      e.chord = std::max(e.chord, (chord - fine).norm());
      ++e.points;
    }
  }
  return e;
}

TEST(CurveInterpolation, ReproducesTheFineCreaseAtRestFarBetterThanChords) {
  for (const char* name : {"four_corner_arcs.svg", "one_curve.svg"}) {
    const DogModel model = build_dog_model(read_crease_pattern(test::dataset(name)), {41, 41});
    const Errors e = rest_errors(model);
    ASSERT_GT(e.points, 10) << name;
    EXPECT_GT(e.chord, 0.01) << name;  // the chord's sagitta is visible on these curved creases
    EXPECT_LT(e.cubic, 0.1 * e.chord) << name;
    EXPECT_LT(e.cubic, 2e-3) << name;
  }
}

TEST(CurveInterpolation, IsExactAtCoarsePointsAndFollowsARigidMotion) {
  const DogModel model =
      build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {21, 21});
  const auto stencils = coarse_curve_stencils(model);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::RowVector3d shift(3, -1, 2);
  const Eigen::MatrixX3d moved_coarse = (model.coarse.V * R.transpose()).rowwise() + shift;
  const Eigen::MatrixX3d moved_fine = (model.fine.V * R.transpose()).rowwise() + shift;
  const Errors at_rest = rest_errors(model);
  for (size_t c = 0; c < stencils.size(); ++c)
    for (size_t k = 0; k < stencils[c].size(); ++k) {
      const auto& cp = model.map.curves[c][k];
      const Eigen::Vector3d fine =
          crease_point_mean(model.fine, moved_fine, model.fine.stitching.curves[c].points[k]);
      const double err = (interpolate(model.coarse, moved_coarse, stencils[c][k]) - fine).norm();
      if (cp.coarse >= 0) {
        EXPECT_EQ(stencils[c][k].count, 1);
        EXPECT_LT(err, 1e-9);
      }
      EXPECT_LT(err, at_rest.cubic + 1e-9);  // weights sum to one: rigid motions commute
    }
}

// The alternative coarse DOG keeps no end of one_curve's crease: its fine end points have no coarse
// points on both sides, and the stencils say so instead of extrapolating from a made-up segment.
TEST(CurveInterpolation, RefusesPointsThatTheAlternativeCoarseDogCannotInterpolate) {
  MeshOptions options;
  options.coarse = CoarseKind::kAlt;
  const DogModel alt =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {41, 27}, options);
  EXPECT_THROW(coarse_curve_stencils(alt), std::logic_error);
  const DogModel standard =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {41, 27});
  EXPECT_NO_THROW(coarse_curve_stencils(standard));
}

}  // namespace
}  // namespace sdog
