#include "geometry/pattern/plane_geometry.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

namespace sdog {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
K::Point_2 cg(const Eigen::Vector2d& p) {
  return K::Point_2(p.x(), p.y());
}
}  // namespace

double signed_area(const Polyline2& polygon) {
  double a = 0;
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const auto& p = polygon[i];
    const auto& q = polygon[(i + 1) % n];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

int orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return static_cast<int>(CGAL::orientation(cg(a), cg(b), cg(c)));
}

bool segments_intersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  return CGAL::do_intersect(K::Segment_2(cg(a), cg(b)), K::Segment_2(cg(c), cg(d)));
}

std::optional<std::pair<double, double>> crossing_parameters(const Eigen::Vector2d& a,
                                                             const Eigen::Vector2d& b,
                                                             const Eigen::Vector2d& c,
                                                             const Eigen::Vector2d& d) {
  const Eigen::Vector2d r = b - a, s = d - c, q = c - a;
  const double denom = r.x() * s.y() - r.y() * s.x();
  if (denom == 0) return std::nullopt;
  const double t = (q.x() * s.y() - q.y() * s.x()) / denom;
  const double u = (q.x() * r.y() - q.y() * r.x()) / denom;
  return std::make_pair(std::clamp(t, 0.0, 1.0), std::clamp(u, 0.0, 1.0));
}

Eigen::Vector2d closest_point_on_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                         const Eigen::Vector2d& b, double* s) {
  const Eigen::Vector2d d = b - a;
  const double len2 = d.squaredNorm();
  double t = len2 > 0 ? (p - a).dot(d) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  if (s) *s = t;
  if (t == 0) return a;
  if (t == 1) return b;
  return a + t * d;
}

int point_in_polygon(const Eigen::Vector2d& p, const Polyline2& polygon) {
  // Winding number with exact orientation tests (Sunday's algorithm).
  int winding = 0;
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const auto& a = polygon[i];
    const auto& b = polygon[(i + 1) % n];
    const int o = orientation(a, b, p);
    if (o == 0 && p.x() >= std::min(a.x(), b.x()) && p.x() <= std::max(a.x(), b.x()) &&
        p.y() >= std::min(a.y(), b.y()) && p.y() <= std::max(a.y(), b.y()))
      return 0;
    if (a.y() <= p.y()) {
      if (b.y() > p.y() && o > 0) ++winding;
    } else if (b.y() <= p.y() && o < 0) {
      --winding;
    }
  }
  return winding != 0 ? 1 : -1;
}

namespace {

// Segment `index` of polyline `poly`: a -> b.
struct Seg {
  int poly, index;
  Eigen::Vector2d a, b;
};

// All segments of the polylines, in order; `lengths` receives their lengths.
std::vector<Seg> collect_segments(const std::vector<const Polyline2*>& polylines,
                                  const std::vector<bool>& closed, std::vector<double>& lengths) {
  std::vector<Seg> segs;
  for (int k = 0; k < static_cast<int>(polylines.size()); ++k) {
    const Polyline2& pts = *polylines[k];
    const int m = segment_count(pts, closed[k]);
    for (int i = 0; i < m; ++i) {
      segs.push_back({k, i, pts[i], pts[(i + 1) % pts.size()]});
      lengths.push_back((segs.back().b - segs.back().a).norm());
    }
  }
  return segs;
}

// Segments by bucket of a uniform grid (hashed, so empty space costs nothing), and the segments
// spanning too many buckets to be listed in each (rare: long straight pieces).
struct SegmentBuckets {
  std::unordered_map<long long, std::vector<int>> grid;
  std::vector<int> large;
};

// Buckets twice the median segment length; bucket indices are clamped, so absurdly far
// coordinates share a bucket and are compared directly.
SegmentBuckets bucket_segments(const std::vector<Seg>& segs, std::vector<double>& lengths) {
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double median = lengths[lengths.size() / 2];
  const double cell = std::isfinite(median) && median > 0 ? 2 * median : 1.0;
  auto bucket_of = [&](double v) {
    const double b = std::floor(v / cell);
    return std::isfinite(b) ? static_cast<long long>(std::clamp(b, -1e9, 1e9)) : 0LL;
  };
  constexpr long long kMaxBucketsPerSegment = 256;
  SegmentBuckets buckets;
  for (int s = 0; s < static_cast<int>(segs.size()); ++s) {
    const auto& g = segs[s];
    const long long x0 = bucket_of(std::min(g.a.x(), g.b.x()));
    const long long x1 = bucket_of(std::max(g.a.x(), g.b.x()));
    const long long y0 = bucket_of(std::min(g.a.y(), g.b.y()));
    const long long y1 = bucket_of(std::max(g.a.y(), g.b.y()));
    if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxBucketsPerSegment) {
      buckets.large.push_back(s);
      continue;
    }
    for (long long y = y0; y <= y1; ++y)
      for (long long x = x0; x <= x1; ++x) buckets.grid[x * 2000000011LL + y].push_back(s);
  }
  return buckets;
}

// Is the pair g1, g2 a contact: do they share a point, and, for consecutive segments of one
// polyline (which share a vertex), do they fold back onto each other?
bool is_contact(const Seg& g1, const Seg& g2, const std::vector<const Polyline2*>& polylines,
                const std::vector<bool>& closed) {
  if (!segments_intersect(g1.a, g1.b, g2.a, g2.b)) return false;
  if (g1.poly == g2.poly) {
    const int n = segment_count(*polylines[g1.poly], closed[g1.poly]);
    const int d = std::abs(g1.index - g2.index);
    const bool consecutive = d == 1 || (closed[g1.poly] && d == n - 1 && n > 2);
    if (consecutive) {
      // They share a vertex; report only a fold-back overlap.
      const Eigen::Vector2d shared = (g1.b == g2.a) ? g1.b : g1.a;
      const Eigen::Vector2d p = (g1.b == g2.a) ? g1.a : g1.b;
      const Eigen::Vector2d q = (g1.b == g2.a) ? g2.b : g2.a;
      const bool overlap = orientation(p, shared, q) == 0 && (p - shared).dot(q - shared) > 0;
      if (!overlap) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<SegmentContact> find_segment_contacts(const std::vector<const Polyline2*>& polylines,
                                                  const std::vector<bool>& closed) {
  std::vector<double> lengths;
  const std::vector<Seg> segs = collect_segments(polylines, closed, lengths);
  std::vector<SegmentContact> out;
  if (segs.size() < 2) return out;
  const SegmentBuckets buckets = bucket_segments(segs, lengths);
  std::set<std::pair<int, int>> seen;
  auto test_pair = [&](int s1, int s2) {
    if (s1 == s2) return;
    if (s1 > s2) std::swap(s1, s2);
    if (!seen.insert({s1, s2}).second) return;
    const Seg& g1 = segs[s1];
    const Seg& g2 = segs[s2];
    if (is_contact(g1, g2, polylines, closed))
      out.push_back({g1.poly, g1.index, g2.poly, g2.index});
  };
  for (const auto& [key, list] : buckets.grid) {
    (void)key;
    for (size_t i = 0; i < list.size(); ++i)
      for (size_t j = i + 1; j < list.size(); ++j) test_pair(list[i], list[j]);
  }
  for (int s : buckets.large)
    for (int t = 0; t < static_cast<int>(segs.size()); ++t) test_pair(s, t);
  std::sort(out.begin(), out.end(), [](const SegmentContact& x, const SegmentContact& y) {
    return std::tie(x.a, x.sa, x.b, x.sb) < std::tie(y.a, y.sa, y.b, y.sb);
  });
  return out;
}

}  // namespace sdog
