#pragma once
// Internal to the SVG reader: flattening of Bézier curves, elliptical arcs and ellipses into
// polylines whose chords deviate from the true curve by at most `tol` (Hausdorff distance).
//
// Béziers: recursive de Casteljau halving until every control point lies within `tol` of the
// chord p0–pn. The curve lies in the convex hull of its control points and the distance to a
// segment is convex, so every curve point is then within `tol` of the chord; and since the curve
// runs continuously from p0 to pn, every chord point has a curve point within `tol` too.
// Depth is limited to kMaxSubdivisionDepth so degenerate input cannot recurse forever.
//
// Arcs (SVG 1.1 F.6.5, endpoint -> centre parameterisation), with φ the x-axis rotation:
//   (x1', y1') = R(-φ) · (p0 - p1) / 2
//   Λ = x1'^2/rx^2 + y1'^2/ry^2;  if Λ > 1: rx *= √Λ, ry *= √Λ               (F.6.6)
//   (cx', cy') = ±√((rx²ry² - rx²y1'² - ry²x1'²) / (rx²y1'² + ry²x1'²)) · (rx y1'/ry, -ry x1'/rx)
//                (+ if large_arc != sweep)
//   c = R(φ) · (cx', cy') + (p0 + p1) / 2
//   θ1 = ∠((1,0), u),  Δθ = ∠(u, v),  u = ((x1'-cx')/rx, (y1'-cy')/ry), v = ((-x1'-cx')/rx,
//   (-y1'-cy')/ry) with Δθ < 0 if !sweep and Δθ > 0 if sweep (adding/subtracting 2π).
// Points are c + R(φ) · (rx cos θ, ry sin θ). A chord spanning Δ of the parameter deviates by
// the sagitta s = r (1 - cos(Δ/2)) = 2 r sin²(Δ/4) on a circle of radius r; the ellipse is a
// linear image of the unit circle with norm max(rx, ry), so Δ ≤ 4 asin(√(tol / (2 max(rx, ry))))
// keeps the deviation ≤ tol. Steps never exceed a quarter turn, so a full ellipse has ≥ 4 points.
//
// Every function appends the points after the start point and the last appended point is the
// given end point itself (bit-identical), never a re-evaluation of the curve at t = 1.
#include "geometry/input/internal/svg_path_data.h"

#include <cstddef>
#include <vector>

namespace sdog::svg {

constexpr int kMaxSubdivisionDepth = 24;

/// Appends points to a polyline, refusing to grow it beyond `max_points`
/// (ElementError "too many points after flattening; simplify the drawing").
class PointSink {
 public:
  PointSink(std::vector<Point>& points, std::size_t max_points)
      : points_(points), max_points_(max_points) {}
  void push(const Point& p);
  std::size_t size() const { return points_.size(); }
  std::size_t max_points() const { return max_points_; }

 private:
  std::vector<Point>& points_;
  std::size_t max_points_;
};

/// cos and sin of an angle in degrees, exact for multiples of 90° (so rotate(90) is exact).
void cos_sin_degrees(double degrees, double& c, double& s);

void flatten_cubic(const Point& p0, const Point& p1, const Point& p2, const Point& p3, double tol,
                   PointSink& out);
void flatten_quadratic(const Point& p0, const Point& p1, const Point& p2, double tol,
                       PointSink& out);

/// Centre parameterisation of an SVG arc (see above). Radii are the corrected ones.
struct ArcCenter {
  Point center = Point::Zero();
  double rx = 0, ry = 0;
  double cos_phi = 1, sin_phi = 0;
  double theta1 = 0, delta_theta = 0;  ///< radians
  Point at(double theta) const;
};

/// False when the arc is a straight line (a zero radius or equal endpoints, F.6.2).
/// Throws ElementError if the computation overflows.
bool arc_center(const Point& p0, double rx, double ry, double rotation_deg, bool large_arc,
                bool sweep, const Point& p1, ArcCenter& out);

/// Number of equal parameter steps for `angle` (radians) of an ellipse with the given largest
/// radius, from the sagitta bound above. Throws if more than `max_points` would be needed.
std::size_t arc_segment_count(double radius, double angle, double tol, std::size_t max_points);

void flatten_arc(const Point& p0, double rx, double ry, double rotation_deg, bool large_arc,
                 bool sweep, const Point& p1, double tol, PointSink& out);

/// A closed axis-aligned ellipse: points at θ = 2πi/n, i = 0..n-1, starting at (cx + rx, cy) and
/// turning like SVG's circle (towards +y in user space); the first point is not repeated.
void flatten_ellipse(const Point& center, double rx, double ry, double tol, PointSink& out);

/// Appends the segment's points after `segment.from`.
void flatten_segment(const PathSegment& segment, double tol, PointSink& out);

}  // namespace sdog::svg
