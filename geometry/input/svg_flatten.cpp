#include "geometry/input/internal/svg_flatten.h"

#include <algorithm>
#include <cmath>

namespace sdog::svg {

namespace {

constexpr double kPi = 3.14159265358979323846;

bool finite(const Point& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y());
}

// a/2 + b/2 cannot overflow where (a + b)/2 can, and is as accurate.
Point mid(const Point& a, const Point& b) {
  return 0.5 * a + 0.5 * b;
}

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const Point ap = p - a;
  const double length2 = ab.squaredNorm();
  if (length2 > 0) {
    const double t = std::clamp(ap.dot(ab) / length2, 0.0, 1.0);
    return (ap - t * ab).norm();
  }
  return ap.norm();
}

[[noreturn]] void not_finite() {
  throw ElementError("coordinate is not a finite number (a curve computation overflows)");
}

void cubic(const Point& p0, const Point& p1, const Point& p2, const Point& p3, double tol,
           int depth, PointSink& out) {
  if (depth >= kMaxSubdivisionDepth ||
      (distance_to_segment(p1, p0, p3) <= tol && distance_to_segment(p2, p0, p3) <= tol)) {
    out.push(p3);
    return;
  }
  const Point p01 = mid(p0, p1), p12 = mid(p1, p2), p23 = mid(p2, p3);
  const Point p012 = mid(p01, p12), p123 = mid(p12, p23);
  const Point m = mid(p012, p123);
  cubic(p0, p01, p012, m, tol, depth + 1, out);
  cubic(m, p123, p23, p3, tol, depth + 1, out);
}

void quadratic(const Point& p0, const Point& p1, const Point& p2, double tol, int depth,
               PointSink& out) {
  if (depth >= kMaxSubdivisionDepth || distance_to_segment(p1, p0, p2) <= tol) {
    out.push(p2);
    return;
  }
  const Point p01 = mid(p0, p1), p12 = mid(p1, p2);
  const Point m = mid(p01, p12);
  quadratic(p0, p01, m, tol, depth + 1, out);
  quadratic(m, p12, p2, tol, depth + 1, out);
}

/// ∠(u, v) in (-π, π].
double angle_between(const Point& u, const Point& v) {
  return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
}

}  // namespace

void PointSink::push(const Point& p) {
  if (points_.size() >= max_points_)
    throw ElementError("too many points after flattening; simplify the drawing");
  points_.push_back(p);
}

void cos_sin_degrees(double degrees, double& c, double& s) {
  double reduced = std::fmod(degrees, 360.0);  // exact
  if (reduced < 0) reduced += 360.0;
  if (reduced == 0) {
    c = 1, s = 0;
  } else if (reduced == 90) {
    c = 0, s = 1;
  } else if (reduced == 180) {
    c = -1, s = 0;
  } else if (reduced == 270) {
    c = 0, s = -1;
  } else {
    const double radians = reduced * (kPi / 180.0);
    c = std::cos(radians);
    s = std::sin(radians);
  }
}

void flatten_cubic(const Point& p0, const Point& p1, const Point& p2, const Point& p3, double tol,
                   PointSink& out) {
  if (!finite(p0) || !finite(p1) || !finite(p2) || !finite(p3)) not_finite();
  cubic(p0, p1, p2, p3, tol, 0, out);
}

void flatten_quadratic(const Point& p0, const Point& p1, const Point& p2, double tol,
                       PointSink& out) {
  if (!finite(p0) || !finite(p1) || !finite(p2)) not_finite();
  quadratic(p0, p1, p2, tol, 0, out);
}

Point ArcCenter::at(double theta) const {
  const double x = rx * std::cos(theta), y = ry * std::sin(theta);
  return center + Point(cos_phi * x - sin_phi * y, sin_phi * x + cos_phi * y);
}

bool arc_center(const Point& p0, double rx, double ry, double rotation_deg, bool large_arc,
                bool sweep, const Point& p1, ArcCenter& out) {
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (rx == 0 || ry == 0 || p0 == p1) return false;
  double cos_phi = 1, sin_phi = 0;
  cos_sin_degrees(rotation_deg, cos_phi, sin_phi);
  const Point half = 0.5 * p0 - 0.5 * p1;
  const double x1 = cos_phi * half.x() + sin_phi * half.y();
  const double y1 = -sin_phi * half.x() + cos_phi * half.y();
  // F.6.6: radii too small to reach the end point are scaled up uniformly.
  // Working with X = x1'/rx, Y = y1'/ry keeps every intermediate in range: the radicand is
  // (1 - Λ)/Λ with Λ = X² + Y², and rx·√Λ = hypot(x1', y1'·rx/ry) for the scaled radius.
  const double X = x1 / rx, Y = y1 / ry;
  const double lambda = X * X + Y * Y;
  if (!(lambda > 0)) return false;  // the chord underflows against the radii: a straight line
  double coefficient = 0;           // Λ ≥ 1: the centre is the chord's midpoint (F.6.6)
  if (lambda > 1) {
    const double scaled_rx = std::hypot(x1, y1 * (rx / ry));
    const double scaled_ry = std::hypot(x1 * (ry / rx), y1);
    rx = scaled_rx;
    ry = scaled_ry;
  } else {
    coefficient = std::sqrt(std::max(0.0, (1 - lambda) / lambda));
    if (large_arc == sweep) coefficient = -coefficient;
  }
  const double cxp = coefficient * rx * Y;
  const double cyp = -coefficient * ry * X;
  const Point middle = 0.5 * p0 + 0.5 * p1;
  out.center = middle + Point(cos_phi * cxp - sin_phi * cyp, sin_phi * cxp + cos_phi * cyp);
  out.rx = rx;
  out.ry = ry;
  out.cos_phi = cos_phi;
  out.sin_phi = sin_phi;
  const Point u((x1 - cxp) / rx, (y1 - cyp) / ry);
  const Point v((-x1 - cxp) / rx, (-y1 - cyp) / ry);
  out.theta1 = angle_between(Point(1, 0), u);
  double delta = angle_between(u, v);
  if (!sweep && delta > 0) delta -= 2 * kPi;
  if (sweep && delta < 0) delta += 2 * kPi;
  out.delta_theta = delta;
  if (!finite(out.center) || !std::isfinite(rx) || !std::isfinite(ry) ||
      !std::isfinite(out.theta1) || !std::isfinite(delta))
    not_finite();
  return true;
}

std::size_t arc_segment_count(double radius, double angle, double tol, std::size_t max_points) {
  angle = std::abs(angle);
  if (!(radius > 0) || angle == 0) return 1;
  if (!std::isfinite(radius) || !std::isfinite(angle)) not_finite();
  const double q = tol / (2 * radius);
  double step = kPi / 2;
  if (q < 0.5) step = std::min(step, 4 * std::asin(std::sqrt(q)));
  const double count = std::ceil(angle / step);
  if (!(step > 0) || !(count <= static_cast<double>(max_points)))
    throw ElementError("too many points after flattening; simplify the drawing");
  return std::max<std::size_t>(1, static_cast<std::size_t>(count));
}

void flatten_arc(const Point& p0, double rx, double ry, double rotation_deg, bool large_arc,
                 bool sweep, const Point& p1, double tol, PointSink& out) {
  ArcCenter arc;
  if (!arc_center(p0, rx, ry, rotation_deg, large_arc, sweep, p1, arc)) {
    out.push(p1);
    return;
  }
  const std::size_t n =
      arc_segment_count(std::max(arc.rx, arc.ry), arc.delta_theta, tol, out.max_points());
  for (std::size_t i = 1; i < n; ++i)
    out.push(
        arc.at(arc.theta1 + arc.delta_theta * (static_cast<double>(i) / static_cast<double>(n))));
  out.push(p1);
}

void flatten_ellipse(const Point& center, double rx, double ry, double tol, PointSink& out) {
  if (!finite(center) || !std::isfinite(rx) || !std::isfinite(ry)) not_finite();
  std::size_t n =
      arc_segment_count(std::max(std::abs(rx), std::abs(ry)), 2 * kPi, tol, out.max_points());
  n = std::max<std::size_t>(n, 4);
  for (std::size_t i = 0; i < n; ++i) {
    double c, s;
    if ((4 * i) % n == 0) {
      cos_sin_degrees(static_cast<double>(4 * i / n) * 90.0, c, s);  // exact quarter points
    } else {
      const double theta = 2 * kPi * static_cast<double>(i) / static_cast<double>(n);
      c = std::cos(theta);
      s = std::sin(theta);
    }
    out.push(Point(center.x() + rx * c, center.y() + ry * s));
  }
}

void flatten_segment(const PathSegment& segment, double tol, PointSink& out) {
  switch (segment.kind) {
    case SegmentKind::kLine:
      out.push(segment.to);
      return;
    case SegmentKind::kQuadratic:
      flatten_quadratic(segment.from, segment.c1, segment.to, tol, out);
      return;
    case SegmentKind::kCubic:
      flatten_cubic(segment.from, segment.c1, segment.c2, segment.to, tol, out);
      return;
    case SegmentKind::kArc:
      flatten_arc(segment.from, segment.rx, segment.ry, segment.rotation_deg, segment.large_arc,
                  segment.sweep, segment.to, tol, out);
      return;
  }
}

}  // namespace sdog::svg
