// Polyline helpers of pattern cleaning (see cleaner.h): inserting points into polylines,
// clustering nearby points, and where two segments touch.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "geometry/pattern/internal/cleaner.h"
#include "geometry/pattern/plane_geometry.h"

namespace sdog::cleaning {
namespace {

// Raw (unclamped) parameter of p along a + t d.
double param_raw(const Vec2& p, const Vec2& a, const Vec2& d) {
  return (p - a).dot(d) / d.squaredNorm();
}

}  // namespace

Polyline2 with_insertions(const Polyline2& pts, bool closed, std::vector<Insertion> ins) {
  std::sort(ins.begin(), ins.end(), [](const Insertion& a, const Insertion& b) {
    return std::tie(a.seg, a.param) < std::tie(b.seg, b.param);
  });
  const int n = static_cast<int>(pts.size());
  const int m = segment_count(pts, closed);
  Polyline2 out;
  size_t k = 0;
  for (int i = 0; i < n; ++i) {
    if (out.empty() || out.back() != pts[i]) out.push_back(pts[i]);
    if (i >= m) continue;
    const Vec2& next = pts[(i + 1) % n];
    for (; k < ins.size() && ins[k].seg == i; ++k)
      if (ins[k].point != out.back() && ins[k].point != next) out.push_back(ins[k].point);
  }
  if (closed && out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

double param_on(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double l2 = (b - a).squaredNorm();
  if (l2 == 0) return 0;
  return std::clamp((p - a).dot(b - a) / l2, 0.0, 1.0);
}

std::vector<std::vector<int>> cluster_points(const std::vector<Vec2>& pts, double tol) {
  const int n = static_cast<int>(pts.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const double cell = tol > 0 ? tol : 1.0;
  std::unordered_map<unsigned long long, std::vector<int>> buckets;
  auto key = [&](long long bx, long long by) {
    return static_cast<unsigned long long>(bx) * 73856093ULL ^
           static_cast<unsigned long long>(by) * 19349663ULL;
  };
  // Bucket indices are clamped: far-away points share a bucket and are compared directly.
  auto bucket = [&](double v) {
    return static_cast<long long>(std::clamp(std::floor(v / cell), -1e12, 1e12));
  };
  for (int i = 0; i < n; ++i) {
    const long long bx = bucket(pts[i].x());
    const long long by = bucket(pts[i].y());
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        auto it = buckets.find(key(bx + dx, by + dy));
        if (it == buckets.end()) continue;
        for (int j : it->second)
          if ((pts[i] - pts[j]).norm() <= tol || pts[i] == pts[j]) parent[find(i)] = find(j);
      }
    buckets[key(bx, by)].push_back(i);
  }
  std::map<int, std::vector<int>> groups;
  for (int i = 0; i < n; ++i) groups[find(i)].push_back(i);
  std::vector<std::vector<int>> out;
  for (auto& [root, members] : groups) out.push_back(std::move(members));
  std::sort(out.begin(), out.end());
  return out;
}

Vec2 mean_of_distinct(const std::vector<Vec2>& pts) {
  std::vector<Vec2> distinct;
  for (const auto& p : pts)
    if (std::find(distinct.begin(), distinct.end(), p) == distinct.end()) distinct.push_back(p);
  Vec2 m = Vec2::Zero();
  for (const auto& p : distinct) m += p;
  return m / static_cast<double>(distinct.size());
}

Vec2 contact_point(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  if (a0 == b0 || a0 == b1) return a0;
  if (a1 == b0 || a1 == b1) return a1;
  if (orientation(b0, b1, a0) == 0) return a0;
  if (orientation(b0, b1, a1) == 0) return a1;
  if (orientation(a0, a1, b0) == 0) return b0;
  if (orientation(a0, a1, b1) == 0) return b1;
  const auto st = crossing_parameters(a0, a1, b0, b1);
  Vec2 p = a0 + st->first * (a1 - a0);
  // Crossings with axis-aligned segments lie exactly on their line.
  if (b0.y() == b1.y()) p.y() = b0.y();
  if (b0.x() == b1.x()) p.x() = b0.x();
  if (a0.y() == a1.y()) p.y() = a0.y();
  if (a0.x() == a1.x()) p.x() = a0.x();
  return p;
}

bool collinear_overlap(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  if (orientation(b0, b1, a0) != 0 || orientation(b0, b1, a1) != 0) return false;
  // Collinear and intersecting: an overlap unless they only share an end.
  const Vec2 d = a1 - a0;
  const double t0 = param_raw(b0, a0, d), t1 = param_raw(b1, a0, d);
  return std::min(1.0, std::max(t0, t1)) > std::max(0.0, std::min(t0, t1));
}

}  // namespace sdog::cleaning
