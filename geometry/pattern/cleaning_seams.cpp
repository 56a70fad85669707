// Pattern cleaning, step 4 for ends inside the sheet: a crease (or slit) that ends far from every
// other curve is continued by a seam, a straight line from its end along its direction there to
// the first crease or boundary it meets, so that the curves divide the sheet into patches.
#include <algorithm>
#include <string>

#include "base/text_format.h"
#include "geometry/pattern/internal/cleaner.h"
#include "geometry/pattern/plane_geometry.h"

namespace sdog::cleaning {
namespace {

// The unit direction in which end e of `points` leaves the curve: from the point at least `reach`
// back along it (or its other end) to the end.
Vec2 end_direction(const Polyline2& points, int e, double reach) {
  const int n = static_cast<int>(points.size());
  const Vec2& end = e == 0 ? points.front() : points.back();
  Vec2 back = end;
  for (int i = 1; i < n && (back - end).norm() < reach; ++i) back = points[e == 0 ? i : n - 1 - i];
  return (end - back).normalized();
}

}  // namespace

// The first point of a crease or boundary loop that the ray from p along `direction` meets
// (`polyline` indexes the creases, then the loops after them); crease k's segments at p do not
// count.
SnapCandidate Cleaner::first_hit(const Vec2& p, const Vec2& direction, int k) const {
  const Vec2 far = p + 4 * size_ * direction;
  SnapCandidate best;
  auto try_polyline = [&](const Polyline2& pts, bool closed, int index) {
    for (int i = 0; i < segment_count(pts, closed); ++i) {
      const Vec2 &a = pts[i], &b = pts[(i + 1) % pts.size()];
      if (index == k && (a == p || b == p)) continue;
      if (!segments_intersect(p, far, a, b)) continue;
      const auto st = crossing_parameters(p, far, a, b);  // clamped to the segments
      if (!st || st->first <= 0) continue;
      const double distance = st->first * (far - p).norm();
      if (distance < best.distance)
        best = {distance, index, i, st->second, a + st->second * (b - a)};
    }
  };
  const int nc = static_cast<int>(creases_.size());
  for (int j = 0; j < nc; ++j) try_polyline(creases_[j].points, creases_[j].closed, j);
  for (size_t l = 0; l < loops_.size(); ++l)
    try_polyline(loops_[l], true, nc + static_cast<int>(l));
  return best;
}

void Cleaner::add_seam(int k, int e) {
  const Vec2 p = end_point(creases_[k], e);
  const SnapCandidate hit = first_hit(p, end_direction(creases_[k].points, e, merge_tol_), k);
  if (hit.polyline < 0) return;  // unreachable: every ray from inside the sheet leaves it
  const int nc = static_cast<int>(creases_.size());
  const bool on_boundary = hit.polyline >= nc;
  Polyline2& target = on_boundary ? loops_[hit.polyline - nc] : creases_[hit.polyline].points;
  const bool closed = on_boundary || creases_[hit.polyline].closed;
  // A vertex of the segment met within merge_tol is taken instead of a new one beside it.
  const Vec2& a = target[hit.seg];
  const Vec2& b = target[(hit.seg + 1) % target.size()];
  Vec2 end = hit.point;
  if ((a - end).norm() <= merge_tol_ || (b - end).norm() <= merge_tol_)
    end = (a - end).norm() <= (b - end).norm() ? a : b;
  else
    target = with_insertions(target, closed, {{hit.seg, hit.param, end}});
  Crease seam;
  seam.points = {p, end};
  seam.fold = Fold::kFlat;
  seam.kind = CurveKind::kSeam;
  seam.origin = "the seam from " + name(k) + "'s end";
  const std::string what =
      creases_[k].kind == CurveKind::kSlit ? "the slit's tip" : "its fold fades to flat there";
  warn(name(k) + " ends inside the sheet at " + format_point(p) + " (" + what +
       "): a seam, stitched and kept smooth, continues it straight to " +
       (on_boundary ? std::string("the sheet boundary") : name(hit.polyline)) + " at " +
       format_point(end));
  creases_.push_back(std::move(seam));
}

}  // namespace sdog::cleaning
