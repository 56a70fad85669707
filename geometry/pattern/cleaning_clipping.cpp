// Pattern cleaning, step 2: creases are clipped to the sheet; where a crease leaves it, the point
// becomes a crease end and a boundary vertex.
#include <algorithm>
#include <set>

#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/pattern/internal/cleaner.h"
#include "geometry/pattern/plane_geometry.h"

namespace sdog::cleaning {

void Cleaner::clip_to_sheet() {
  const int nc = static_cast<int>(creases_.size());
  const std::vector<std::vector<Insertion>> crease_events = cut_at_boundary();
  std::vector<Crease> kept;
  for (int k = 0; k < nc; ++k) clip_crease(k, crease_events[k], kept);
  creases_ = std::move(kept);
}

// Finds where creases touch the boundary, inserts those points into the boundary loops and
// returns them per crease (the cuts of step 2). Throws for a crease running along the boundary.
std::vector<std::vector<Insertion>> Cleaner::cut_at_boundary() {
  const int nc = static_cast<int>(creases_.size());
  std::vector<const Polyline2*> polys;
  std::vector<bool> closed;
  for (const auto& c : creases_) polys.push_back(&c.points), closed.push_back(c.closed);
  for (const auto& l : loops_) polys.push_back(&l), closed.push_back(true);
  std::vector<std::vector<Insertion>> crease_events(nc), loop_events(loops_.size());
  for (const auto& c : find_segment_contacts(polys, closed)) {
    if (c.a >= nc || c.b < nc) continue;  // only crease/boundary contacts
    const Polyline2& cp = creases_[c.a].points;
    const Polyline2& lp = loops_[c.b - nc];
    const Vec2 &a0 = cp[c.sa], &a1 = cp[(c.sa + 1) % cp.size()];
    const Vec2 &b0 = lp[c.sb], &b1 = lp[(c.sb + 1) % lp.size()];
    if (collinear_overlap(a0, a1, b0, b1))
      throw InputError(name(c.a) + " runs along the sheet boundary near " +
                       format_point(0.5 * (a0 + a1)) +
                       "; the boundary is not a crease: remove that part of the crease");
    const Vec2 p = contact_point(a0, a1, b0, b1);
    crease_events[c.a].push_back({c.sa, param_on(p, a0, a1), p});
    loop_events[c.b - nc].push_back({c.sb, param_on(p, b0, b1), p});
  }
  for (size_t l = 0; l < loops_.size(); ++l)
    if (!loop_events[l].empty()) loops_[l] = with_insertions(loops_[l], true, loop_events[l]);
  return crease_events;
}

// Appends to `kept` the parts of crease k inside the sheet, cut at its boundary contacts `events`
// (a crease without contacts is kept whole or dropped whole).
void Cleaner::clip_crease(int k, const std::vector<Insertion>& events, std::vector<Crease>& kept) {
  const Crease& crease = creases_[k];
  if (events.empty()) {
    if (sheet_side(crease.points.front()) == 1) {
      kept.push_back(crease);
    } else {
      log(name(k) + " lies outside the sheet; removed");
    }
    return;
  }
  std::set<std::pair<double, double>> cuts;
  for (const auto& e : events) cuts.insert({e.point.x(), e.point.y()});
  Polyline2 pts = with_insertions(crease.points, crease.closed, events);
  if (crease.closed) {
    // Start the loop at a cut so that it splits like an open curve.
    auto it = std::find_if(pts.begin(), pts.end(), [&](const Vec2& p) {
      return cuts.count({p.x(), p.y()}) > 0;
    });
    std::rotate(pts.begin(), it, pts.end());
    pts.push_back(pts.front());
  }
  keep_inside_pieces(k, pts, cuts, kept);
}

// Splits the open polyline `pts` of crease k at the `cuts` and appends the pieces inside the
// sheet to `kept` (as open creases), logging how many pieces outside were dropped.
void Cleaner::keep_inside_pieces(int k, const Polyline2& pts,
                                 const std::set<std::pair<double, double>>& cuts,
                                 std::vector<Crease>& kept) {
  const Crease& crease = creases_[k];
  int pieces = 0, dropped = 0;
  Polyline2 piece;
  for (size_t i = 0; i < pts.size(); ++i) {
    piece.push_back(pts[i]);
    const bool cut = cuts.count({pts[i].x(), pts[i].y()}) > 0 || i + 1 == pts.size();
    if (!cut || piece.size() < 2) {
      if (cut) piece = {pts[i]};
      continue;
    }
    if (sheet_side(0.5 * (piece[0] + piece[1])) == 1) {
      Crease part = crease;
      part.closed = false;
      part.points = piece;
      kept.push_back(std::move(part));
      ++pieces;
    } else {
      ++dropped;
    }
    piece = {pts[i]};
  }
  if (dropped > 0)
    log(name(k) + ": " + std::to_string(dropped) + " part(s) outside the sheet removed, " +
        std::to_string(pieces) + " kept");
}

}  // namespace sdog::cleaning
