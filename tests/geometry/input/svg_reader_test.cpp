// Tests of the SVG reader (geometry/input/svg_reader.h) and its internal parsers. Expected values
// are computed independently of the implementation: analytic curves, hand-derived arc centres,
// hand-composed transforms.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "base/errors.h"
#include "geometry/input/internal/svg_flatten.h"
#include "geometry/input/internal/svg_path_data.h"
#include "geometry/input/internal/svg_style.h"
#include "geometry/input/svg_reader.h"

namespace {

using sdog::InputError;
using sdog::SvgCurve;
using sdog::SvgDrawing;
using Vec = Eigen::Vector2d;

constexpr double kPi = 3.14159265358979323846;

std::string document(const std::string& body,
                     const std::string& root_attributes = "viewBox=\"0 0 100 100\"") {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" " + root_attributes + ">\n" + body +
         "\n</svg>\n";
}

SvgDrawing parse(const std::string& body, double flatness = 1e-5,
                 const std::string& root_attributes = "viewBox=\"0 0 100 100\"") {
  sdog::SvgReadOptions options;
  options.flatness = flatness;
  return sdog::parse_svg(document(body, root_attributes), "test.svg", options);
}

std::vector<SvgCurve> path_curves(const std::string& d, double flatness = 1e-5) {
  return parse("<path d=\"" + d + "\"/>", flatness).curves;
}

/// The single curve of a one-element drawing.
SvgCurve only_curve(const std::string& body, double flatness = 1e-5) {
  const SvgDrawing drawing = parse(body, flatness);
  EXPECT_EQ(drawing.curves.size(), 1u) << body;
  if (drawing.curves.empty()) return {};
  return drawing.curves.front();
}

/// Converts y-up output back to SVG user space.
Vec svg_space(const Vec& p) {
  return Vec(p.x(), -p.y());
}

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

std::string parse_error(const std::string& body) {
  return error_of([&] { parse(body); });
}

void expect_points(const SvgCurve& curve, const std::vector<Vec>& svg_points) {
  ASSERT_EQ(curve.points.size(), svg_points.size());
  for (std::size_t i = 0; i < svg_points.size(); ++i) {
    EXPECT_EQ(curve.points[i].x(), svg_points[i].x()) << "point " << i;
    EXPECT_EQ(curve.points[i].y(), -svg_points[i].y()) << "point " << i;
  }
}

void expect_same_points(const SvgCurve& a, const SvgCurve& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i], b.points[i]) << i;
}

void expect_near_point(const Vec& actual, const Vec& expected, double tolerance = 1e-9) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
}

double distance_to_segment(const Vec& p, const Vec& a, const Vec& b) {
  const Vec ab = b - a;
  const double t =
      ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

double distance_to_polyline(const Vec& p, const std::vector<Vec>& points, bool closed) {
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    best = std::min(best, distance_to_segment(p, points[i], points[i + 1]));
  if (closed) best = std::min(best, distance_to_segment(p, points.back(), points.front()));
  return best;
}

Vec cubic_point(const Vec& p0, const Vec& p1, const Vec& p2, const Vec& p3, double t) {
  const double s = 1 - t;
  return s * s * s * p0 + 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t * p3;
}

// ----------------------------------------------------------------------------------------------
// Numbers and path grammar

TEST(SvgNumbers, FollowThePathGrammar) {
  std::string_view text = "1.5.5 10-5 -.5e1 +2E-1 7.e1 3e";
  std::vector<double> values;
  std::size_t pos = 0;
  double v = 0;
  while (true) {
    sdog::svg::skip_wsp(text, pos);
    if (sdog::svg::scan_number(text, pos, v) != sdog::svg::NumberScan::kOk) break;
    values.push_back(v);
  }
  EXPECT_EQ(values, (std::vector<double>{1.5, 0.5, 10, -5, -5, 0.2, 70, 3}));
  EXPECT_EQ(text.substr(pos), "e");  // an exponent needs digits
}

TEST(SvgNumbers, RefuseNonFiniteSpellingsAndOverflow) {
  for (std::string_view text :
       {"nan", "NaN", "-inf", "Infinity", "1e999", "-1e400", "1e99999999999"}) {
    std::size_t pos = 0;
    double v = 0;
    EXPECT_EQ(sdog::svg::scan_number(text, pos, v), sdog::svg::NumberScan::kNotFinite) << text;
  }
  std::size_t pos = 0;
  double v = 1;
  ASSERT_EQ(sdog::svg::scan_number("1e-999", pos, v), sdog::svg::NumberScan::kOk);
  EXPECT_EQ(v, 0.0);
  pos = 0;
  EXPECT_EQ(sdog::svg::scan_number(".", pos, v), sdog::svg::NumberScan::kAbsent);
  EXPECT_EQ(sdog::svg::scan_number("-", pos, v), sdog::svg::NumberScan::kAbsent);
}

TEST(SvgPath, MovesAndLinesReadAbsoluteAndRelativeCoordinates) {
  const auto curves = path_curves("M10 20 L30 40 l5 -5 L 0.5,0.25");
  ASSERT_EQ(curves.size(), 1u);
  expect_points(curves[0], {{10, 20}, {30, 40}, {35, 35}, {0.5, 0.25}});
  EXPECT_FALSE(curves[0].closed);
  EXPECT_EQ(curves[0].element, "path");
}

TEST(SvgPath, HorizontalAndVerticalLinesMoveOneCoordinate) {
  const auto curves = path_curves("M1 2 H10 V20 h-3 v-4");
  ASSERT_EQ(curves.size(), 1u);
  expect_points(curves[0], {{1, 2}, {10, 2}, {10, 20}, {7, 20}, {7, 16}});
}

TEST(SvgPath, RepeatedCoordinatesRepeatTheCommand) {
  expect_points(path_curves("M0 0 10 10 20 0")[0], {{0, 0}, {10, 10}, {20, 0}});
  expect_points(path_curves("m1 1 2 2 3 3")[0], {{1, 1}, {3, 3}, {6, 6}});
  expect_points(path_curves("M0,0L1,1,2,2 3 3")[0], {{0, 0}, {1, 1}, {2, 2}, {3, 3}});
  expect_points(path_curves("M0 0h1 2v3 4")[0], {{0, 0}, {1, 0}, {3, 0}, {3, 3}, {3, 7}});
  expect_same_points(path_curves("M0 0 C1 2 3 4 5 6 7 8 9 10 11 12")[0],
                     path_curves("M0 0 C1 2 3 4 5 6 C7 8 9 10 11 12")[0]);
}

TEST(SvgPath, NumbersWithoutSeparatorsAreSplitByTheGrammar) {
  expect_points(path_curves("M1.5.5 10-5")[0], {{1.5, 0.5}, {10, -5}});
  expect_points(path_curves("M-.5e1,+2E-1L3,4")[0], {{-5, 0.2}, {3, 4}});
}

TEST(SvgPath, RelativeCubicMatchesAbsolute) {
  expect_same_points(path_curves("M10 10 c10 0 20 10 20 20")[0],
                     path_curves("M10 10 C20 10 30 20 30 30")[0]);
  const auto curve = path_curves("M10 10 c10 0 20 10 20 20")[0];
  EXPECT_GT(curve.points.size(), 3u);  // actually flattened
}

TEST(SvgPath, SmoothCubicReflectsPreviousControlPoint) {
  expect_same_points(path_curves("M0 0 C10 20 30 20 40 0 S70 -20 80 0")[0],
                     path_curves("M0 0 C10 20 30 20 40 0 C50 -20 70 -20 80 0")[0]);
  expect_same_points(path_curves("M0 0 C10 20 30 20 40 0 s30 -20 40 0")[0],
                     path_curves("M0 0 C10 20 30 20 40 0 C50 -20 70 -20 80 0")[0]);
  // S after S reflects the previous S's second control point.
  expect_same_points(path_curves("M0 0 C0 10 10 10 10 0 S20 -10 20 0 S30 10 30 0")[0],
                     path_curves("M0 0 C0 10 10 10 10 0 C10 -10 20 -10 20 0 C20 10 30 10 30 0")[0]);
  // Without a previous cubic the first control point is the current point.
  expect_same_points(path_curves("M0 0 L5 5 S30 20 40 0")[0],
                     path_curves("M0 0 L5 5 C5 5 30 20 40 0")[0]);
}

TEST(SvgPath, SmoothQuadraticReflectsPreviousControlPoint) {
  expect_same_points(path_curves("M0 0 Q10 20 20 0 T40 0 T60 0")[0],
                     path_curves("M0 0 Q10 20 20 0 Q30 -20 40 0 Q50 20 60 0")[0]);
  expect_same_points(path_curves("M0 0 q10 20 20 0 t20 0")[0],
                     path_curves("M0 0 Q10 20 20 0 Q30 -20 40 0")[0]);
  // T without a previous quadratic is a straight line.
  expect_points(path_curves("M0 0 T10 10")[0], {{0, 0}, {10, 10}});
}

TEST(SvgPath, QuadraticPointsLieNearTheCurve) {
  const double flatness = 1e-4, tol = flatness * 100;
  const auto curve = path_curves("M0 0 Q50 100 100 0", flatness)[0];
  ASSERT_GT(curve.points.size(), 4u);
  std::vector<Vec> points;
  for (const Vec& p : curve.points) points.push_back(svg_space(p));
  for (int i = 0; i <= 2000; ++i) {
    const double t = i / 2000.0;
    const Vec q =
        (1 - t) * (1 - t) * Vec(0, 0) + 2 * (1 - t) * t * Vec(50, 100) + t * t * Vec(100, 0);
    EXPECT_LE(distance_to_polyline(q, points, false), tol * (1 + 1e-9)) << t;
  }
}

TEST(SvgPath, ArcFlagsWithoutSeparators) {
  expect_same_points(path_curves("M0 0 a10 10 0 1010 10")[0],
                     path_curves("M0 0 A10 10 0 1 0 10 10")[0]);
  expect_same_points(path_curves("M0 0 a10,10,0,0,1,10,10")[0],
                     path_curves("M0 0 A10 10 0 0 1 10 10")[0]);
}

/// Arc from (0,0) to (10,0) with radius 10: the centres are (5, ±5√3). In SVG user space (y down)
/// sweep=1 turns towards increasing angles. Around (5, 5√3) the end points are at -120° and -60°;
/// around (5, -5√3) at 120° and 60°. The midpoints of the four arcs follow.
TEST(SvgPath, EveryArcFlagCombinationPicksItsArc) {
  const double h = 5 * std::sqrt(3.0);
  struct Case {
    int large, sweep;
    Vec center, midpoint;
  };
  const Case cases[] = {
      {0, 1, {5, h}, {5, h - 10}},    // small arc, -120° -> -60° through -90°
      {1, 0, {5, h}, {5, h + 10}},    // large arc, -120° -> -420° through 90°
      {0, 0, {5, -h}, {5, 10 - h}},   // small arc, 120° -> 60° through 90°
      {1, 1, {5, -h}, {5, -h - 10}},  // large arc, 120° -> 420° through 270°
  };
  const double flatness = 1e-4, tol = flatness * 100;
  std::vector<std::size_t> counts;
  for (const Case& c : cases) {
    const std::string d =
        "M0 0 A10 10 0 " + std::to_string(c.large) + " " + std::to_string(c.sweep) + " 10 0";
    SCOPED_TRACE(d);
    const auto curves = path_curves(d, flatness);
    ASSERT_EQ(curves.size(), 1u);
    std::vector<Vec> points;
    for (const Vec& p : curves[0].points) points.push_back(svg_space(p));
    EXPECT_EQ(points.front(), Vec(0, 0));
    EXPECT_EQ(points.back(), Vec(10, 0));
    for (const Vec& p : points) EXPECT_NEAR((p - c.center).norm(), 10, 1e-9);
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
      EXPECT_LE(10 - (0.5 * (points[i] + points[i + 1]) - c.center).norm(), tol);
    EXPECT_LE(distance_to_polyline(c.midpoint, points, false), tol);
    counts.push_back(points.size());
  }
  EXPECT_GT(counts[1], counts[0]);  // large arcs need more points
  EXPECT_GT(counts[3], counts[2]);
}

TEST(SvgPath, ArcRadiiTooSmallAreScaledUp) {
  // Radius 1 cannot reach from (0,0) to (10,0): scaled to 5, centre (5,0); sweep=1 goes from
  // 180° through 270° (y down: (5,-5)) to 360°.
  const double tol = 1e-4 * 100;
  const auto curve = path_curves("M0 0 A1 1 0 0 1 10 0", 1e-4)[0];
  std::vector<Vec> points;
  for (const Vec& p : curve.points) points.push_back(svg_space(p));
  ASSERT_GT(points.size(), 4u);
  for (const Vec& p : points) EXPECT_NEAR((p - Vec(5, 0)).norm(), 5, 1e-9);
  EXPECT_LE(distance_to_polyline(Vec(5, -5), points, false), tol);
  EXPECT_EQ(points.back(), Vec(10, 0));
}

TEST(SvgPath, RotatedEllipticalArcStaysOnItsEllipse) {
  // Ellipse centred at (50,50), rx=20, ry=10 rotated by 30°: from θ=0 to θ=90° (sweep=1, small).
  const double phi = 30 * kPi / 180;
  const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(phi).toRotationMatrix();
  const Vec center(50, 50);
  const Vec p0 = center + rotation * Vec(20, 0), p1 = center + rotation * Vec(0, 10);
  char d[200];
  std::snprintf(d, sizeof d, "M%.17g %.17g A20 10 30 0 1 %.17g %.17g", p0.x(), p0.y(), p1.x(),
                p1.y());
  const auto curve = path_curves(d, 1e-5)[0];
  ASSERT_GT(curve.points.size(), 5u);
  for (const Vec& p : curve.points) {
    const Vec local = rotation.transpose() * (svg_space(p) - center);
    EXPECT_NEAR(std::hypot(local.x() / 20, local.y() / 10), 1, 1e-9);
    EXPECT_GE(local.x(), -1e-9);  // the quarter θ ∈ [0°, 90°]
    EXPECT_GE(local.y(), -1e-9);
  }
}

TEST(SvgPath, ZeroRadiusArcIsALineAndEqualEndpointsAreOmitted) {
  expect_points(path_curves("M0 0 A0 5 0 0 1 10 10")[0], {{0, 0}, {10, 10}});
  expect_points(path_curves("M0 0 L5 0 A5 5 0 0 1 5 0 L5 5")[0], {{0, 0}, {5, 0}, {5, 5}});
}

TEST(SvgPath, SubpathsStartAtMovesAndCloseAtZ) {
  const auto curves = path_curves("M0 0 L10 0 L10 10 Z M20 20 L30 20");
  ASSERT_EQ(curves.size(), 2u);
  expect_points(curves[0], {{0, 0}, {10, 0}, {10, 10}});
  EXPECT_TRUE(curves[0].closed);
  EXPECT_EQ(curves[0].subpath, 0);
  expect_points(curves[1], {{20, 20}, {30, 20}});
  EXPECT_FALSE(curves[1].closed);
  EXPECT_EQ(curves[1].subpath, 1);
}

TEST(SvgPath, RelativeMoveAfterCloseStartsFromSubpathStart) {
  const auto curves = path_curves("M10 10 L20 10 L20 20 z m5 5 l1 0");
  ASSERT_EQ(curves.size(), 2u);
  expect_points(curves[1], {{15, 15}, {16, 15}});
}

TEST(SvgPath, DrawingAfterCloseStartsANewSubpathAtTheStart) {
  const auto curves = path_curves("M0 0 L10 0 L10 10 Z L5 5");
  ASSERT_EQ(curves.size(), 2u);
  expect_points(curves[1], {{0, 0}, {5, 5}});
}

TEST(SvgPath, ClosedCurvesDoNotRepeatTheFirstPoint) {
  const auto curves = path_curves("M0 0 L10 0 L10 10 L0 0 Z");
  ASSERT_EQ(curves.size(), 1u);
  expect_points(curves[0], {{0, 0}, {10, 0}, {10, 10}});
  EXPECT_TRUE(curves[0].closed);
}

TEST(SvgPath, LoneMovesAndDuplicatesAreDropped) {
  const auto curves = path_curves("M0 0 M5 5 L5 5 L6 6 M9 9");
  ASSERT_EQ(curves.size(), 1u);
  expect_points(curves[0], {{5, 5}, {6, 6}});
  EXPECT_EQ(curves[0].subpath, 0);
  EXPECT_TRUE(path_curves("M1 1 z").empty());
}

TEST(SvgPath, EmptyDataDrawsNothing) {
  EXPECT_TRUE(parse("<path d=\"\"/><path d=\"  \"/><path/>").curves.empty());
}

// ----------------------------------------------------------------------------------------------
// Exactness and flatness

TEST(SvgExactness, YIsNegatedExactly) {
  const auto curve = path_curves("M0.1 0.3 L0.7 0")[0];
  EXPECT_EQ(curve.points[0].x(), 0.1);
  EXPECT_EQ(curve.points[0].y(), -0.3);
  EXPECT_EQ(curve.points[1].y(), 0.0);
  EXPECT_FALSE(std::signbit(curve.points[1].y()));  // no -0 in the output
}

TEST(SvgExactness, CurveEndpointsAreTheParsedEndpoints) {
  // Relative end points are previous + delta in double, and curves end exactly there.
  const auto curve = path_curves(
      "M0.1 0.2 c0.3 0.3 0.6 0.3 0.7 0.1 q0.1 0.3 0.3 0.3 "
      "a0.3 0.2 10 0 1 0.9 0.1")[0];
  const double x1 = 0.1 + 0.7, y1 = 0.2 + 0.1;
  const double x2 = x1 + 0.3, y2 = y1 + 0.3;
  const double x3 = x2 + 0.9, y3 = y2 + 0.1;
  bool found1 = false, found2 = false;
  for (const Vec& p : curve.points) {
    found1 |= p == Vec(x1, -y1);
    found2 |= p == Vec(x2, -y2);
  }
  EXPECT_TRUE(found1);
  EXPECT_TRUE(found2);
  EXPECT_EQ(curve.points.back(), Vec(x3, -y3));
}

TEST(SvgExactness, ReadsAnIllustratorSampleExactly) {
  const std::string text =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<svg version=\"1.1\" id=\"Layer_1\" xmlns=\"http://www.w3.org/2000/svg\" x=\"0px\" "
      "y=\"0px\" viewBox=\"0 0 543.1 399.4\" xml:space=\"preserve\">\n"
      "<style type=\"text/css\">\n"
      "\t.st0{fill:none;stroke:#EF4545;stroke-miterlimit:10;}\n"
      "</style>\n"
      "<path class=\"st0\" d=\"M433.6,399.4c-17-23.9-111.6-189.1-298.6-191C80.9,207.9,34.8,217.5,0,"
      "231.8\"/>\n"
      "</svg>\n";
  const SvgDrawing drawing = sdog::parse_svg(text, "sample.svg");
  EXPECT_EQ(drawing.source, "sample.svg");
  ASSERT_TRUE(drawing.has_viewbox);
  EXPECT_EQ(drawing.viewbox.xmin, 0);
  EXPECT_EQ(drawing.viewbox.ymin, -399.4);
  EXPECT_EQ(drawing.viewbox.xmax, 543.1);
  EXPECT_EQ(drawing.viewbox.ymax, 0);
  ASSERT_EQ(drawing.curves.size(), 1u);
  const SvgCurve& curve = drawing.curves[0];
  EXPECT_EQ(curve.colour, "#ef4545");
  EXPECT_FALSE(curve.is_boundary);
  EXPECT_FALSE(curve.dashed);
  EXPECT_FALSE(curve.closed);
  EXPECT_EQ(curve.line, 6);
  EXPECT_EQ(curve.points.front(), Vec(433.6, -399.4));
  EXPECT_EQ(curve.points.back(), Vec(0, -231.8));
  // The end of the relative cubic, computed as a renderer does.
  const Vec joint(433.6 + -298.6, -(399.4 + -191));
  EXPECT_NE(std::find(curve.points.begin(), curve.points.end(), joint), curve.points.end());
}

TEST(SvgFlatness, CubicChordDeviationIsWithinTolerance) {
  const Vec p0(0, 0), p1(30, 100), p2(70, -100), p3(100, 0);
  for (double flatness : {1e-3, 1e-4}) {
    const double tol = flatness * 200;  // viewBox 200 x 100
    const SvgDrawing drawing =
        parse("<path d=\"M0 0 C30 100 70 -100 100 0\"/>", flatness, "viewBox=\"0 0 200 100\"");
    ASSERT_EQ(drawing.curves.size(), 1u);
    std::vector<Vec> points;
    for (const Vec& p : drawing.curves[0].points) points.push_back(svg_space(p));
    // Every curve point is near the polyline...
    std::vector<Vec> samples;
    for (int i = 0; i <= 20000; ++i) samples.push_back(cubic_point(p0, p1, p2, p3, i / 20000.0));
    double worst = 0;
    for (const Vec& q : samples) worst = std::max(worst, distance_to_polyline(q, points, false));
    EXPECT_LE(worst, tol * (1 + 1e-9));
    // ...and every chord point near the curve (up to the sampling step of the curve).
    double step = 0;
    for (std::size_t i = 1; i < samples.size(); ++i)
      step = std::max(step, (samples[i] - samples[i - 1]).norm());
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
      for (int k = 1; k < 8; ++k) {
        const Vec c = points[i] + (points[i + 1] - points[i]) * (k / 8.0);
        double best = INFINITY;
        for (const Vec& q : samples) best = std::min(best, (q - c).norm());
        EXPECT_LE(best, tol + step);
      }
  }
}

TEST(SvgFlatness, SmallerFlatnessGivesMorePoints) {
  std::size_t previous = 0;
  for (double flatness : {1e-2, 5e-3, 2.5e-3, 1.25e-3}) {
    const auto curve = path_curves("M0 0 C30 100 70 -100 100 0", flatness)[0];
    EXPECT_GT(curve.points.size(), previous) << flatness;
    previous = curve.points.size();
  }
  const auto coarse = only_curve("<circle r=\"40\" cx=\"50\" cy=\"50\"/>", 1e-3);
  const auto fine = only_curve("<circle r=\"40\" cx=\"50\" cy=\"50\"/>", 5e-4);
  EXPECT_GT(fine.points.size(), coarse.points.size());
}

TEST(SvgFlatness, ToleranceWithoutViewBoxUsesTheControlPointExtent) {
  // Control points span x 0..1000 and y -1000..1000: extent 2000, tol = 1e-3 * 2000 = 2.
  sdog::SvgReadOptions options;
  options.flatness = 1e-3;
  const SvgDrawing drawing =
      sdog::parse_svg("<svg><path d=\"M0 0 C300 1000 700 -1000 1000 0\"/></svg>", "x.svg", options);
  EXPECT_FALSE(drawing.has_viewbox);
  ASSERT_EQ(drawing.curves.size(), 1u);
  std::vector<Vec> points;
  for (const Vec& p : drawing.curves[0].points) points.push_back(svg_space(p));
  double worst = 0;
  for (int i = 0; i <= 5000; ++i)
    worst = std::max(worst, distance_to_polyline(cubic_point({0, 0}, {300, 1000}, {700, -1000},
                                                             {1000, 0}, i / 5000.0),
                                                 points, false));
  EXPECT_LE(worst, 2.0);
  EXPECT_GT(worst, 0.1);  // not flattened to a far smaller tolerance (e.g. flatness * 1) either
}

TEST(SvgFlatness, TransformedCurvesKeepTheToleranceInRootUnits) {
  // A unit circle scaled by 100: the tolerance 1e-5 * 1000 = 0.01 applies after scaling.
  const double tol = 0.01;
  const SvgDrawing drawing =
      parse("<circle r=\"1\" cx=\"0\" cy=\"0\" transform=\"translate(500 500) scale(100)\"/>", 1e-5,
            "viewBox=\"0 0 1000 1000\"");
  ASSERT_EQ(drawing.curves.size(), 1u);
  const auto& points = drawing.curves[0].points;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec a = svg_space(points[i]), b = svg_space(points[(i + 1) % points.size()]);
    EXPECT_NEAR((a - Vec(500, 500)).norm(), 100, 1e-9);
    EXPECT_LE(100 - (0.5 * (a + b) - Vec(500, 500)).norm(), tol);
  }
  // With only 100x fewer points the sagitta would exceed tol: the count reflects the scale.
  EXPECT_GT(points.size(), 100u);
}

// ----------------------------------------------------------------------------------------------
// Basic shapes

TEST(SvgShapes, CirclesBecomeClosedCurvesOfTheirRadius) {
  const double tol = 1e-4 * 100;
  const SvgCurve curve = only_curve("<circle id=\"c\" cx=\"50\" cy=\"40\" r=\"30\"/>", 1e-4);
  EXPECT_TRUE(curve.closed);
  EXPECT_EQ(curve.element, "circle");
  EXPECT_EQ(curve.id, "c");
  ASSERT_GT(curve.points.size(), 8u);
  EXPECT_EQ(curve.points.front(), Vec(80, -40));
  EXPECT_NE(curve.points.back(), curve.points.front());
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    const Vec a = svg_space(curve.points[i]);
    const Vec b = svg_space(curve.points[(i + 1) % curve.points.size()]);
    EXPECT_NEAR((a - Vec(50, 40)).norm(), 30, 1e-9);
    const double sagitta = 30 - (0.5 * (a + b) - Vec(50, 40)).norm();
    EXPECT_LE(sagitta, tol);
    EXPECT_GT(sagitta, 0);
  }
}

TEST(SvgShapes, EllipsesBecomeClosedCurvesOfTheirRadii) {
  const SvgCurve curve = only_curve("<ellipse cx=\"50\" cy=\"40\" rx=\"30\" ry=\"10\"/>");
  EXPECT_TRUE(curve.closed);
  for (const Vec& p : curve.points) {
    const Vec q = svg_space(p) - Vec(50, 40);
    EXPECT_NEAR(std::hypot(q.x() / 30, q.y() / 10), 1, 1e-12);
  }
  // A missing radius takes the other one (SVG 2 "auto").
  const SvgCurve round = only_curve("<ellipse cx=\"0\" cy=\"0\" rx=\"5\"/>");
  for (const Vec& p : round.points) EXPECT_NEAR(p.norm(), 5, 1e-12);
  EXPECT_TRUE(parse("<ellipse rx=\"0\" ry=\"3\"/><circle r=\"0\"/>").curves.empty());
}

TEST(SvgShapes, RectLinePolylineAndPolygonBecomeCurves) {
  const SvgDrawing drawing = parse(
      "<rect x=\"1\" y=\"2\" width=\"10\" height=\"20\" rx=\"3\"/>\n"
      "<line x1=\"1\" y1=\"2\" x2=\"3\" y2=\"4\"/>\n"
      "<polyline points=\"0,0 10,0 10,10\"/>\n"
      "<polygon points=\"0 0, 5 0, 5 5, 0 0\"/>\n"
      "<rect width=\"0\" height=\"5\"/>\n"
      "<line x1=\"3\" y1=\"3\" x2=\"3\" y2=\"3\"/>");
  ASSERT_EQ(drawing.curves.size(), 4u);
  expect_points(drawing.curves[0], {{1, 2}, {11, 2}, {11, 22}, {1, 22}});
  EXPECT_TRUE(drawing.curves[0].closed);
  EXPECT_EQ(drawing.curves[0].element, "rect");
  expect_points(drawing.curves[1], {{1, 2}, {3, 4}});
  EXPECT_FALSE(drawing.curves[1].closed);
  expect_points(drawing.curves[2], {{0, 0}, {10, 0}, {10, 10}});  // lines keep their vertices
  EXPECT_FALSE(drawing.curves[2].closed);
  expect_points(drawing.curves[3], {{0, 0}, {5, 0}, {5, 5}});
  EXPECT_TRUE(drawing.curves[3].closed);
  EXPECT_EQ(drawing.curves[3].line, 5);
}

TEST(SvgShapes, LengthUnitsAreConvertedToUserUnits) {
  const SvgCurve curve = only_curve("<line x1=\"1in\" y1=\"0\" x2=\"25.4mm\" y2=\"12pt\"/>");
  EXPECT_DOUBLE_EQ(curve.points[0].x(), 96);
  EXPECT_DOUBLE_EQ(curve.points[1].x(), 96);
  EXPECT_DOUBLE_EQ(curve.points[1].y(), -16);
  EXPECT_NE(parse_error("<line x1=\"10%\" x2=\"5\"/>").find("percentage"), std::string::npos);
}

// ----------------------------------------------------------------------------------------------
// Transforms

TEST(SvgTransforms, GroupAndElementTransformsCompose) {
  // rotate(90) maps (1,0) to (0,1), then translate(10,20): (10,21). Exact for quarter turns.
  const SvgCurve curve = only_curve(
      "<g transform=\"translate(10,20)\"><path transform=\"rotate(90)\" d=\"M1 0 L2 0\"/></g>");
  expect_points(curve, {{10, 21}, {10, 22}});
}

TEST(SvgTransforms, NestedTranslateRotateAndScaleCompose) {
  // scale(2) ∘ translate(1,1) ∘ rotate(30) ∘ scale(3, 1) applied to (1, 1).
  const SvgCurve curve = only_curve(
      "<g transform=\"scale(2)\"><g transform=\"translate(1 1)\">"
      "<path transform=\"rotate(30) scale(3,1)\" d=\"M0 0 L1 1\"/></g></g>");
  const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  const Vec scaled(3, 1);
  const Vec rotated(c * scaled.x() - s * scaled.y(), s * scaled.x() + c * scaled.y());
  const Vec expected = 2 * (rotated + Vec(1, 1));
  ASSERT_EQ(curve.points.size(), 2u);
  expect_near_point(svg_space(curve.points[0]), Vec(2, 2));
  expect_near_point(svg_space(curve.points[1]), expected);
}

TEST(SvgTransforms, RotationsTurnAboutTheirCentre) {
  expect_points(only_curve("<path transform=\"rotate(90 5 5)\" d=\"M10 5 L5 5\"/>"),
                {{5, 10}, {5, 5}});
  const SvgCurve curve =
      only_curve("<path transform=\"rotate(-45, 10, 20)\" d=\"M20 20 L10 20\"/>");
  const double r = std::sqrt(0.5) * 10;
  expect_near_point(svg_space(curve.points[0]), Vec(10 + r, 20 - r));
  expect_near_point(svg_space(curve.points[1]), Vec(10, 20));
}

TEST(SvgTransforms, SkewAndMatrixTransformsApply) {
  expect_near_point(
      svg_space(only_curve("<path transform=\"skewX(45)\" d=\"M0 0 L2 3\"/>").points[1]),
      Vec(5, 3));
  const double t30 = std::tan(kPi / 6);
  expect_near_point(
      svg_space(only_curve("<path transform=\"skewY(30)\" d=\"M0 0 L2 3\"/>").points[1]),
      Vec(2, 3 + 2 * t30));
  // matrix(1 2 3 4 5 6): (1,1) -> (1 + 3 + 5, 2 + 4 + 6).
  expect_points(only_curve("<path transform=\"matrix(1,2,3,4,5,6)\" d=\"M1 1 L0 0\"/>"),
                {{9, 12}, {5, 6}});
}

TEST(SvgTransforms, ListsApplyRightToLeft) {
  // translate(10) scale(2): (1,1) -> (2,2) -> (12,2).
  expect_points(only_curve("<path transform=\"translate(10) scale(2)\" d=\"M1 1 L0 0\"/>"),
                {{12, 2}, {10, 0}});
  expect_points(only_curve("<path transform=\" translate(10,0) , scale(2) \" d=\"M1 1 L0 0\"/>"),
                {{12, 2}, {10, 0}});
}

TEST(SvgTransforms, TheParserAndAffineMapsGiveHandComputedValues) {
  const sdog::svg::Affine t = sdog::svg::parse_transform("scale(2,3)");
  EXPECT_DOUBLE_EQ(t.max_stretch(), 3);
  EXPECT_NEAR(sdog::svg::parse_transform("rotate(17)").max_stretch(), 1, 1e-15);
  EXPECT_TRUE(sdog::svg::parse_transform("").is_identity());
  for (const char* bad : {"rotate(1,2)", "scale()", "translate(1", "foo(1)", "rotate 5",
                          "matrix(1 2 3 4 5)", "scale(1,,2)"})
    EXPECT_THROW(sdog::svg::parse_transform(bad), sdog::svg::ElementError) << bad;
}

// ----------------------------------------------------------------------------------------------
// Colours and styles

TEST(SvgStyle, ReadsEveryColourFormat) {
  using sdog::svg::parse_colour;
  EXPECT_EQ(parse_colour("#ABC"), "#aabbcc");
  EXPECT_EQ(parse_colour(" #EF4545 "), "#ef4545");
  EXPECT_EQ(parse_colour("rgb(255, 0, 16)"), "#ff0010");
  EXPECT_EQ(parse_colour("rgb(100%,0%,50%)"), "#ff0080");
  EXPECT_EQ(parse_colour("RGB(300 -4 0)"), "#ff0000");
  EXPECT_EQ(parse_colour("DarkRed"), "#8b0000");
  EXPECT_EQ(parse_colour("black"), "#000000");
  EXPECT_EQ(parse_colour("white"), "#ffffff");
  EXPECT_EQ(parse_colour("green"), "#008000");
  for (const char* bad : {"#12", "#ggg", "rgb(1,2)", "rgb(1,2,3", "bluish", ""})
    EXPECT_THROW(parse_colour(bad), sdog::svg::ElementError) << bad;
}

TEST(SvgStyle, TheStrokeAttributeSetsTheColour) {
  const SvgCurve curve = only_curve("<path stroke=\"red\" d=\"M0 0 L1 1\"/>");
  EXPECT_EQ(curve.colour, "#ff0000");
  EXPECT_FALSE(curve.is_boundary);
}

TEST(SvgStyle, InlineStyleOverClassOverAttribute) {
  const std::string sheet = "<style>.a{stroke:#0000ff}</style>";
  EXPECT_EQ(only_curve(sheet + "<path class=\"a\" stroke=\"red\" style=\"fill:none; stroke: "
                               "#00FF00 !important\" d=\"M0 0 L1 1\"/>")
                .colour,
            "#00ff00");
  EXPECT_EQ(only_curve(sheet + "<path class=\"a\" stroke=\"red\" d=\"M0 0 L1 1\"/>").colour,
            "#0000ff");
  EXPECT_EQ(only_curve(sheet + "<path stroke=\"red\" d=\"M0 0 L1 1\"/>").colour, "#ff0000");
}

TEST(SvgStyle, LaterRulesWinAmongClasses) {
  const std::string sheet = "<style>.a{stroke:red} .b{stroke:blue}</style>";
  EXPECT_EQ(only_curve(sheet + "<path class=\"b a\" d=\"M0 0 L1 1\"/>").colour, "#0000ff");
  EXPECT_EQ(only_curve(sheet + "<path class=\"a\" d=\"M0 0 L1 1\"/>").colour, "#ff0000");
}

TEST(SvgStyle, ReadsStylesheetRules) {
  const std::string sheet =
      "<defs><style type=\"text/css\"><![CDATA[\n"
      "  /* crease colours */\n"
      "  .st0 , .st1 {\n    fill: none;\n    stroke: #EF4545; }\n"
      "  @media print { .st2 { stroke: green } }\n"
      "  g .st3 { stroke: green }\n"
      "  .st2{stroke-dasharray:4 2;stroke:#3F48CC}.st3{stroke:#000}\n"
      "]]></style></defs>";
  const SvgDrawing drawing =
      parse(sheet +
            "<path class=\"st1\" d=\"M0 0 L1 1\"/><path class=\"st2\" d=\"M0 0 L1 1\"/>"
            "<path class=\"st3\" d=\"M0 0 L1 1\"/>");
  ASSERT_EQ(drawing.curves.size(), 3u);
  EXPECT_EQ(drawing.curves[0].colour, "#ef4545");
  EXPECT_EQ(drawing.curves[1].colour, "#3f48cc");
  EXPECT_TRUE(drawing.curves[1].dashed);
  EXPECT_EQ(drawing.curves[2].colour, "#000000");
  EXPECT_TRUE(drawing.curves[2].is_boundary);
}

TEST(SvgStyle, GroupsPassTheirStyleToChildren) {
  EXPECT_EQ(only_curve("<g stroke=\"#123456\"><g><path d=\"M0 0 L1 1\"/></g></g>").colour,
            "#123456");
  EXPECT_EQ(only_curve("<g stroke=\"red\"><g style=\"stroke:blue\"><path d=\"M0 0 L1 1\"/></g></g>")
                .colour,
            "#0000ff");
  // The element's own attribute beats a style inherited from its parent.
  EXPECT_EQ(
      only_curve("<g style=\"stroke:blue\"><path stroke=\"red\" d=\"M0 0 L1 1\"/></g>").colour,
      "#ff0000");
  EXPECT_EQ(only_curve("<g stroke=\"blue\"><path stroke=\"inherit\" d=\"M0 0 L1 1\"/></g>").colour,
            "#0000ff");
  EXPECT_EQ(
      only_curve("<style>.k{stroke:lime}</style><g class=\"k\"><path d=\"M0 0 L1 1\"/></g>").colour,
      "#00ff00");
}

TEST(SvgStyle, FillGivesTheColourWithoutAStroke) {
  EXPECT_EQ(only_curve("<path fill=\"#00ff00\" d=\"M0 0 L1 1\"/>").colour, "#00ff00");
  EXPECT_EQ(only_curve("<path stroke=\"none\" fill=\"blue\" d=\"M0 0 L1 1\"/>").colour, "#0000ff");
  EXPECT_EQ(only_curve("<g fill=\"blue\"><path stroke=\"none\" d=\"M0 0 L1 1\"/></g>").colour,
            "#0000ff");
  const SvgCurve unpainted = only_curve("<path d=\"M0 0 L1 1\"/>");
  EXPECT_EQ(unpainted.colour, "#000000");
  EXPECT_TRUE(unpainted.is_boundary);
  EXPECT_EQ(only_curve("<path fill=\"none\" stroke=\"none\" d=\"M0 0 L1 1\"/>").colour, "#000000");
  EXPECT_EQ(only_curve("<path stroke=\"url(#g) red\" d=\"M0 0 L1 1\"/>").colour, "#ff0000");
  EXPECT_EQ(
      only_curve("<g color=\"teal\"><path stroke=\"currentColor\" d=\"M0 0 L1 1\"/></g>").colour,
      "#008080");
  const SvgCurve near_black = only_curve("<path stroke=\"#000001\" d=\"M0 0 L1 1\"/>");
  EXPECT_FALSE(near_black.is_boundary);
}

TEST(SvgStyle, DashedStrokesAreDetected) {
  const SvgDrawing drawing = parse(
      "<style>.d{stroke-dasharray:3,3}</style>"
      "<path stroke-dasharray=\"5,3\" d=\"M0 0 L1 1\"/>"
      "<path stroke-dasharray=\"none\" d=\"M0 0 L1 1\"/>"
      "<g stroke-dasharray=\"2\"><path d=\"M0 0 L1 1\"/></g>"
      "<path class=\"d\" d=\"M0 0 L1 1\"/>"
      "<path style=\"stroke-dasharray:0, 0\" d=\"M0 0 L1 1\"/>"
      "<g stroke-dasharray=\"2\"><path style=\"stroke-dasharray:none\" d=\"M0 0 L1 1\"/></g>"
      "<path d=\"M0 0 L1 1\"/>");
  std::vector<bool> dashed;
  for (const SvgCurve& curve : drawing.curves) dashed.push_back(curve.dashed);
  EXPECT_EQ(dashed, (std::vector<bool>{true, false, true, true, false, false, false}));
}

TEST(SvgStyle, HiddenAndNonRenderedElementsAreSkipped) {
  const SvgDrawing drawing = parse(
      "<defs><path id=\"d\" d=\"M0 0 L1 1\"/><use href=\"#d\"/></defs>"
      "<metadata><path d=\"M0 0 L1 1\"/></metadata>"
      "<clipPath><rect width=\"1\" height=\"1\"/></clipPath>"
      "<mask><path d=\"M0 0 L1 1\"/></mask><symbol><path d=\"M0 0 L1 1\"/></symbol>"
      "<pattern><path d=\"M0 0 L1 1\"/></pattern><marker><path d=\"M0 0 L1 1\"/></marker>"
      "<g display=\"none\"><path d=\"M0 0 L1 1\"/></g>"
      "<path style=\"display:none\" d=\"M0 0 L1 1\"/>"
      "<text x=\"0\" y=\"0\">label</text>"
      "<a><path id=\"kept\" d=\"M0 0 L1 1\"/></a>");
  ASSERT_EQ(drawing.curves.size(), 1u);
  EXPECT_EQ(drawing.curves[0].id, "kept");
}

TEST(SvgStyle, CurvesKeepDocumentOrderAndSourceLines) {
  const SvgDrawing drawing = parse(
      "<g>\n<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\"/>\n</g>\n<path d=\"M0 0 L1 1 M2 2 L3 3\"/>");
  ASSERT_EQ(drawing.curves.size(), 3u);
  EXPECT_EQ(drawing.curves[0].element, "line");
  EXPECT_EQ(drawing.curves[0].line, 3);
  EXPECT_EQ(drawing.curves[1].line, 5);
  EXPECT_EQ(drawing.curves[2].line, 5);
  EXPECT_EQ(drawing.curves[2].subpath, 1);
}

// ----------------------------------------------------------------------------------------------
// viewBox

TEST(SvgViewBox, ToleratesWhitespaceAndCommas) {
  const SvgDrawing drawing = parse("", 1e-5, "viewBox=\" 10,20 , 30\n40 \"");
  ASSERT_TRUE(drawing.has_viewbox);
  EXPECT_EQ(drawing.viewbox.xmin, 10);
  EXPECT_EQ(drawing.viewbox.xmax, 40);
  EXPECT_EQ(drawing.viewbox.ymin, -60);
  EXPECT_EQ(drawing.viewbox.ymax, -20);
}

TEST(SvgViewBox, FallsBackOnWidthAndHeight) {
  SvgDrawing drawing = parse("", 1e-5, "width=\"200px\" height=\"100\"");
  ASSERT_TRUE(drawing.has_viewbox);
  EXPECT_EQ(drawing.viewbox.xmin, 0);
  EXPECT_EQ(drawing.viewbox.xmax, 200);
  EXPECT_EQ(drawing.viewbox.ymin, -100);
  EXPECT_EQ(drawing.viewbox.ymax, 0);
  drawing = parse("", 1e-5, "width=\"254mm\" height=\"1in\"");
  EXPECT_DOUBLE_EQ(drawing.viewbox.xmax, 960);
  EXPECT_DOUBLE_EQ(drawing.viewbox.ymin, -96);
  EXPECT_FALSE(parse("", 1e-5, "").has_viewbox);
  EXPECT_FALSE(parse("", 1e-5, "width=\"100%\" height=\"100%\"").has_viewbox);
}

TEST(SvgViewBox, DegenerateIsAcceptedButNonNumericIsNot) {
  EXPECT_TRUE(parse("", 1e-5, "viewBox=\"0 0 0 -5\"").has_viewbox);
  for (const char* bad : {"viewBox=\"0 0 nan 1\"", "viewBox=\"0 0 10\"", "viewBox=\"0 0 a b\"",
                          "viewBox=\"0 0 1e999 1\"", "viewBox=\"0 0 inf 1\""}) {
    const std::string message = error_of([&] { parse("", 1e-5, bad); });
    EXPECT_NE(message.find("test.svg:1: <svg>: viewBox: "), std::string::npos) << message;
  }
}

// ----------------------------------------------------------------------------------------------
// Errors

TEST(SvgErrors, AMissingFileOrADirectoryIsAnInputError) {
  const std::string missing = ::testing::TempDir() + "/sdog_no_such_file.svg";
  EXPECT_EQ(error_of([&] { sdog::read_svg_file(missing); }),
            missing + ": cannot open file (No such file or directory)");
  const std::string directory = ::testing::TempDir();
  EXPECT_NE(
      error_of([&] { sdog::read_svg_file(directory); }).find("cannot open file (Is a directory)"),
      std::string::npos);
}

TEST(SvgErrors, AFileIsReadFromDisk) {
  const std::string path = ::testing::TempDir() + "/sdog_svg_reader_test.svg";
  {
    std::ofstream out(path);
    out << document("<path d=\"M1 2 L3 4\"/>");
  }
  const SvgDrawing drawing = sdog::read_svg_file(path);
  EXPECT_EQ(drawing.source, path);
  ASSERT_EQ(drawing.curves.size(), 1u);
  expect_points(drawing.curves[0], {{1, 2}, {3, 4}});
  std::filesystem::remove(path);
}

TEST(SvgErrors, NonXmlAndAWrongRootAreRefused) {
  std::string message = error_of([] { sdog::parse_svg("hello <", "a.svg"); });
  EXPECT_EQ(message.rfind("a.svg:1: not an XML file: ", 0), 0u) << message;
  EXPECT_NE(message.find(" at byte "), std::string::npos);
  message = error_of([] { sdog::parse_svg("<svg>\n<g>\n</svg>", "b.svg"); });
  EXPECT_NE(message.find("b.svg:3: not an XML file"), std::string::npos) << message;
  EXPECT_NE(error_of([] { sdog::parse_svg("", "e.svg"); }).find("not an XML file"),
            std::string::npos);
  EXPECT_EQ(error_of([] { sdog::parse_svg("<html><svg/></html>", "c.svg"); }),
            "c.svg: the root element is <html>, expected <svg>");
}

TEST(SvgErrors, APathSyntaxErrorNamesFileLineElementAndCharacter) {
  const std::string text =
      "<svg viewBox=\"0 0 10 10\">\n<g>\n<path id=\"c3\" d=\"M 0 0 C 10\"/>\n</g></svg>";
  const std::string message = error_of([&] { sdog::parse_svg(text, "pattern.svg"); });
  EXPECT_EQ(message.rfind("pattern.svg:3: <path id=\"c3\">: path data: expected a number after 'C' "
                          "at character 11 (\"",
                          0),
            0u)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(SvgErrors, EveryPathSyntaxErrorSaysWhatWasExpected) {
  struct Case {
    const char* d;
    const char* expected;
  };
  const Case cases[] = {
      {"L 0 0", "must start with 'M' or 'm'"},
      {"M 0 0 X 5", "unexpected character 'X'"},
      {"M 0 0 Z 5", "unexpected number after 'Z'"},
      {"M 0 0 A 1 1 0 2 0 5 5", "expected an arc flag (0 or 1) after 'A'"},
      {"M 0 0 L 10,, 5", "expected a number after 'L'"},
      {"M 0 0 L 1 5e", "unexpected character 'e'"},
      {"M 0 0 L 1e 5", "expected a number after 'L'"},
      {"M 0 0 L 5", "expected a number after 'L'"},
      {"M,0 0", "expected a number after 'M'"},
      {"M 0 0 L 5 5,", "expected a number after 'L'"},
      {"M 0 0 q 1 2 3", "expected a number after 'q'"},
  };
  for (const Case& c : cases) {
    const std::string message = parse_error(std::string("<path d=\"") + c.d + "\"/>");
    EXPECT_NE(message.find(std::string("test.svg:2: <path>: path data: ") + c.expected),
              std::string::npos)
        << c.d << " -> " << message;
  }
}

TEST(SvgErrors, NonFiniteCoordinatesAreRefused) {
  for (const char* body :
       {"<path d=\"M0 0 L nan 5\"/>", "<path d=\"M0 0 L inf 5\"/>", "<path d=\"M0 0 L 1e999 5\"/>",
        "<path d=\"M0 0 L 5 -Infinity\"/>", "<path d=\"M1e308 0 l1e308 0\"/>",
        "<polyline points=\"0 0 nan 1\"/>", "<circle r=\"1e999\"/>", "<line x1=\"inf\"/>",
        "<path transform=\"translate(nan)\" d=\"M0 0 L1 1\"/>",
        "<path transform=\"scale(1e300)\" d=\"M0 0 L1e300 1\"/>"}) {
    const std::string message = parse_error(body);
    EXPECT_NE(message.find("not a finite number"), std::string::npos) << body << " -> " << message;
  }
  for (const char* body :
       {"<path transform=\"skewX(90)\" d=\"M0 0 L1 1\"/>",
        "<g transform=\"scale(1e200)\"><path transform=\"scale(1e200)\" d=\"M0 0 L1 1\"/></g>"})
    EXPECT_NE(parse_error(body).find("transform: the transform is not finite"), std::string::npos)
        << body;
}

TEST(SvgErrors, UnsupportedElementsAndBadAttributesAreRefused) {
  EXPECT_EQ(
      parse_error("<g><use id=\"u1\" href=\"#x\"/></g>"),
      "test.svg:2: <use id=\"u1\">: <use> is not supported; ungroup/expand it in your editor");
  EXPECT_NE(parse_error("<polygon points=\"0 0 1\"/>").find("points: odd number of coordinates"),
            std::string::npos);
  EXPECT_NE(parse_error("<path stroke=\"bluish\" d=\"M0 0 L1 1\"/>")
                .find("stroke: unrecognised colour 'bluish'"),
            std::string::npos);
  EXPECT_NE(parse_error("<path stroke=\"url(#grad)\" d=\"M0 0 L1 1\"/>").find("not supported"),
            std::string::npos);
  EXPECT_NE(parse_error("<circle r=\"-1\"/>").find("negative radius"), std::string::npos);
  EXPECT_NE(parse_error("<rect width=\"-1\" height=\"2\"/>").find("negative"), std::string::npos);
  EXPECT_NE(parse_error("<path transform=\"rotate(1,2)\" d=\"M0 0 L1 1\"/>")
                .find("transform: rotate takes 1 or 3 numbers, got 2"),
            std::string::npos);
}

TEST(SvgErrors, TooManyPointsAreRefused) {
  sdog::SvgReadOptions options;
  options.flatness = 1e-300;
  const std::string message = error_of([&] {
    sdog::parse_svg(document("<circle cx=\"50\" cy=\"50\" r=\"50\"/>"), "t.svg", options);
  });
  EXPECT_NE(message.find("too many points after flattening"), std::string::npos) << message;
  // Deep recursion on a cubic is bounded by the point budget as well.
  const std::string cubic = error_of([&] {
    sdog::parse_svg(document("<path d=\"M0 0 C0 100 100 100 100 0\"/>"), "t.svg", options);
  });
  EXPECT_NE(cubic.find("too many points after flattening"), std::string::npos) << cubic;
}

TEST(SvgErrors, DeepNestingIsRefused) {
  std::string body;
  for (int i = 0; i < 1000; ++i) body += "<g>";
  body += "<path d=\"M0 0 L1 1\"/>";
  for (int i = 0; i < 1000; ++i) body += "</g>";
  EXPECT_NE(parse_error(body).find("nested"), std::string::npos);
}

TEST(SvgErrors, BadFlatnessIsAUsageError) {
  sdog::SvgReadOptions options;
  options.flatness = 0;
  EXPECT_THROW(sdog::parse_svg(document(""), "t.svg", options), sdog::UsageError);
}

// ----------------------------------------------------------------------------------------------
// Flattening internals

TEST(SvgFlattenInternals, ArcSegmentCountFollowsTheSagitta) {
  // r = 1, tol = 1e-4: the largest step Δ has 2 sin²(Δ/4) = 1e-4.
  const double step = 4 * std::asin(std::sqrt(0.5e-4));
  const std::size_t n = sdog::svg::arc_segment_count(1, kPi, 1e-4, 1000000);
  EXPECT_EQ(n, static_cast<std::size_t>(std::ceil(kPi / step)));
  EXPECT_EQ(sdog::svg::arc_segment_count(1, 2 * kPi, 10, 1000000), 4u);  // quarter steps at most
  EXPECT_THROW(sdog::svg::arc_segment_count(1, kPi, 1e-30, 1000000), sdog::svg::ElementError);
}

TEST(SvgFlattenInternals, LastPointIsTheEndPointItself) {
  std::vector<Vec> points;
  sdog::svg::PointSink sink(points, 100000);
  const Vec p0(0.1, 0.7), p1(3.3, 9.1), p2(-4.7, 2.9), p3(1.0 / 3.0, 2.0 / 7.0);
  sdog::svg::flatten_cubic(p0, p1, p2, p3, 1e-6, sink);
  EXPECT_EQ(points.back(), p3);
  sdog::svg::flatten_quadratic(p3, p1, p0, 1e-6, sink);
  EXPECT_EQ(points.back(), p0);
  sdog::svg::flatten_arc(p0, 3, 2, 17, true, false, p3, 1e-6, sink);
  EXPECT_EQ(points.back(), p3);
}

TEST(SvgFlattenInternals, ADegenerateCubicTerminates) {
  std::vector<Vec> points;
  sdog::svg::PointSink sink(points, 100000);
  sdog::svg::flatten_cubic(Vec(1, 1), Vec(1, 1), Vec(1, 1), Vec(1, 1), 1e-9, sink);
  EXPECT_EQ(points.size(), 1u);
}

}  // namespace
