// Pattern cleaning, step 4: a crease end that is still free snaps to the nearest crease vertex,
// else onto the boundary, else onto another crease (a T junction); an end farther than that from
// everything gets a seam when seams are allowed (cleaning_seams.cpp), else the pattern is
// rejected.
#include <cmath>
#include <string>

#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/pattern/internal/cleaner.h"
#include "geometry/pattern/plane_geometry.h"

namespace sdog::cleaning {

void Cleaner::snap_free_ends() {
  for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
    if (creases_[k].closed) continue;
    for (int e = 0; e < 2; ++e) {
      const Vec2 p = end_point(creases_[k], e);
      if (sheet_side(p) == 0) continue;
      const auto counts = vertex_counts();
      if (counts.at({p.x(), p.y()}) >= 2) continue;  // a junction already
      snap_end(k, e, counts);
    }
  }
}

// Snaps end e of crease k (see the file comment); an end farther than snap_tol from everything
// gets a seam when seams are allowed, else it is rejected.
void Cleaner::snap_end(int k, int e, const VertexCounts& counts) {
  const Vec2 p = end_point(creases_[k], e);
  if (snap_to_crease_vertex(k, e, p, counts)) return;
  const SnapCandidate bnd = nearest_boundary_point(p);
  if (bnd.distance <= snap_tol_) {
    const Polyline2& lp = loops_[bnd.polyline];
    const Vec2 &b0 = lp[bnd.seg], &b1 = lp[(bnd.seg + 1) % lp.size()];
    Vec2 on_bnd = bnd.point;
    if (b0.y() == b1.y()) on_bnd.y() = b0.y();
    if (b0.x() == b1.x()) on_bnd.x() = b0.x();
    loops_[bnd.polyline] = with_insertions(lp, true, {{bnd.seg, bnd.param, on_bnd}});
    end_point(creases_[k], e) = on_bnd;
    log(name(k) + ": end " + format_point(p) + " moved onto the sheet boundary at " +
        format_point(on_bnd));
    return;
  }
  const SnapCandidate crease = nearest_crease_point(k, e, p);
  if (crease.distance <= snap_tol_) {
    Crease& oc = creases_[crease.polyline];
    oc.points = with_insertions(oc.points, oc.closed, {{crease.seg, crease.param, crease.point}});
    end_point(creases_[k], e) = crease.point;
    log(name(k) + ": end " + format_point(p) + " joined " + name(crease.polyline) + " at " +
        format_point(crease.point));
    return;
  }
  if (seams_) return add_seam(k, e);
  throw InputError(name(k) + " ends at " + format_point(p) + ", " + format_number(bnd.distance) +
                   " units from the sheet boundary" +
                   (std::isfinite(crease.distance)
                        ? " and " + format_number(crease.distance) + " from the nearest crease"
                        : std::string()) +
                   "; creases must end on the boundary or on another crease (tolerance " +
                   format_number(snap_tol_) + " = " + format_number(snap_fraction_) +
                   " L, --snap-tol)");
}

// (a) Moves end e (at p) of crease k to the nearest crease vertex (a junction or a boundary end
// of another crease) within snap_tol, if there is one.
bool Cleaner::snap_to_crease_vertex(int k, int e, const Vec2& p, const VertexCounts& counts) {
  double best = INFINITY;
  Vec2 target;
  for (const auto& [key, count] : counts) {
    const Vec2 q(key.first, key.second);
    if (q == p) continue;
    const bool vertex = (count >= 2 && sheet_side(q) == 1) || is_boundary_end(q, k);
    if (vertex && (q - p).norm() < best) best = (q - p).norm(), target = q;
  }
  if (best <= snap_tol_) {
    end_point(creases_[k], e) = target;
    log(name(k) + ": end " + format_point(p) + " snapped to the crease vertex " +
        format_point(target));
    return true;
  }
  return false;
}

// (b) The point of the sheet boundary nearest to p (`polyline` is the loop).
SnapCandidate Cleaner::nearest_boundary_point(const Vec2& p) const {
  SnapCandidate best;
  for (size_t l = 0; l < loops_.size(); ++l) {
    const Polyline2& lp = loops_[l];
    for (size_t i = 0; i < lp.size(); ++i) {
      double s;
      const Vec2 q = closest_point_on_segment(p, lp[i], lp[(i + 1) % lp.size()], &s);
      if ((q - p).norm() < best.distance)
        best.distance = (q - p).norm(), best.polyline = static_cast<int>(l),
        best.seg = static_cast<int>(i), best.param = s, best.point = q;
    }
  }
  return best;
}

// (c) The crease point nearest to p, end e of crease k (`polyline` is the crease); crease k
// itself counts away from this end.
SnapCandidate Cleaner::nearest_crease_point(int k, int e, const Vec2& p) const {
  SnapCandidate best;
  for (int j = 0; j < static_cast<int>(creases_.size()); ++j) {
    const Polyline2& cp = creases_[j].points;
    const int m = segment_count(cp, creases_[j].closed);
    double along = 0;  // arc length from this end, for the crease itself
    for (int i = 0; i < m; ++i) {
      const int idx = (j == k && e == 1) ? m - 1 - i : i;
      Vec2 a = cp[idx], b = cp[(idx + 1) % cp.size()];
      if (j == k && !trim_near_end(e, a, b, along)) continue;
      double s;
      const Vec2 q = closest_point_on_segment(p, a, b, &s);
      if ((q - p).norm() < best.distance) {
        best.distance = (q - p).norm();
        best.polyline = j;
        best.seg = idx;
        best.param = param_on(q, cp[idx], cp[(idx + 1) % cp.size()]);
        best.point = q;
      }
    }
  }
  return best;
}

// For the snapping crease's own segment [a, b], walked from end e: skips the part within
// 3 snap_tol of that end (it is the end itself) by moving a (or b for e = 1). `along` is the arc
// length walked so far; false when the whole segment is skipped.
bool Cleaner::trim_near_end(int e, Vec2& a, Vec2& b, double& along) const {
  const double len = (b - a).norm(), limit = 3 * snap_tol_;
  along += len;
  if (along <= limit) return false;
  const double cut = (limit - (along - len)) / len;  // fraction of the segment to skip
  if (cut > 0) {
    if (e == 1)
      b = b + cut * (a - b);
    else
      a = a + cut * (b - a);
  }
  return true;
}

bool Cleaner::is_boundary_end(const Vec2& q, int except) const {
  for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
    if (k == except || creases_[k].closed) continue;
    const auto& c = creases_[k].points;
    if ((c.front() == q || c.back() == q) && sheet_side(q) == 0) return true;
  }
  return false;
}

}  // namespace sdog::cleaning
