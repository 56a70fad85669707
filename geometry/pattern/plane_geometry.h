#pragma once
// Small 2D helpers on double coordinates shared by pattern building and cleaning. Predicates that
// decide topology (orientation, segment intersection) are exact (CGAL filtered predicates).
#include <Eigen/Core>
#include <optional>
#include <vector>

namespace sdog {

using Polyline2 = std::vector<Eigen::Vector2d>;

/// An axis-aligned box.
struct Box2 {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  double width() const { return xmax - xmin; }
  double height() const { return ymax - ymin; }
};

/// Signed area of a closed polygon (shoelace formula), positive when counter-clockwise.
double signed_area(const Polyline2& polygon);

/// Exact orientation of (a, b, c): +1 left turn, -1 right turn, 0 collinear.
int orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

/// Exact test: do the closed segments [a,b] and [c,d] share a point?
bool segments_intersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        const Eigen::Vector2d& c, const Eigen::Vector2d& d);

/// Parameters (s on [a,b], u on [c,d]) of the crossing of two non-parallel segments, computed in
/// double: a + s (b - a) = c + u (d - c). Empty when parallel.
std::optional<std::pair<double, double>> crossing_parameters(const Eigen::Vector2d& a,
                                                             const Eigen::Vector2d& b,
                                                             const Eigen::Vector2d& c,
                                                             const Eigen::Vector2d& d);

/// Closest point to p on segment [a,b]; `s` receives its parameter in [0,1].
Eigen::Vector2d closest_point_on_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                         const Eigen::Vector2d& b, double* s = nullptr);

/// Exact point-in-polygon test by winding number. Returns +1 inside, 0 on the boundary,
/// -1 outside. The polygon is closed implicitly (last point connects to the first).
int point_in_polygon(const Eigen::Vector2d& p, const Polyline2& polygon);

/// Segment i of a polyline: points[i] -> points[(i+1) % n] for closed ones.
inline int segment_count(const Polyline2& points, bool closed) {
  const int n = static_cast<int>(points.size());
  return closed ? (n >= 2 ? n : 0) : std::max(0, n - 1);
}

/// A pair of segments that share a point: (polyline a, segment sa) and (polyline b, segment sb).
struct SegmentContact {
  int a, sa, b, sb;
};

/// All pairs of segments of the given polylines that share a point (exact test), found with a
/// uniform bucket grid. Pairs of consecutive segments of one polyline are reported only when they
/// overlap beyond their shared vertex. Pairs are ordered (a, sa) < (b, sb).
std::vector<SegmentContact> find_segment_contacts(const std::vector<const Polyline2*>& polylines,
                                                  const std::vector<bool>& closed);

}  // namespace sdog
