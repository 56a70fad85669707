// Pattern cleaning, steps 3 and 5: crossings and contacts between creases become junctions at
// exact shared vertices, and nearby junction coordinates are aligned.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/pattern/internal/cleaner.h"
#include "geometry/pattern/plane_geometry.h"

namespace sdog::cleaning {
namespace {

// p with its `axis` coordinate set to t.
Vec2 with_coordinate(Vec2 p, int axis, double t) {
  p[axis] = t;
  return p;
}

// Cumulative arc length at each vertex of every crease (for closed ones also back at the start).
std::vector<std::vector<double>> crease_arc_lengths(const std::vector<Crease>& creases) {
  std::vector<std::vector<double>> arc(creases.size());
  for (size_t k = 0; k < creases.size(); ++k) {
    const auto& p = creases[k].points;
    const int m = segment_count(p, creases[k].closed);
    arc[k].assign(1, 0.0);
    for (int i = 0; i < m; ++i)
      arc[k].push_back(arc[k].back() + (p[(i + 1) % p.size()] - p[i]).norm());
  }
  return arc;
}

// Arc length at global parameter g (segment index + parameter on the segment) of one crease.
double arc_at(const std::vector<double>& arc, double g) {
  const int i = std::min(static_cast<int>(g), static_cast<int>(arc.size()) - 2);
  return arc[i] + (g - i) * (arc[i + 1] - arc[i]);
}

// Rotates a closed crease's points to start in the middle of the largest gap between junction
// passes and appends the start point, so that it can be rerouted as an open curve; shifts the
// passes' parameters to match.
void open_loop_between_passes(Polyline2& pts, std::vector<JunctionPass>& passes) {
  const int n = static_cast<int>(pts.size());
  std::vector<double> gs;
  for (const auto& r : passes) gs.push_back(r.gmin), gs.push_back(r.gmax);
  std::sort(gs.begin(), gs.end());
  double best_gap = -1, start = 0;
  for (size_t i = 0; i < gs.size(); ++i) {
    const double next = i + 1 < gs.size() ? gs[i + 1] : gs[0] + n;
    if (next - gs[i] > best_gap) best_gap = next - gs[i], start = gs[i] + 0.5 * (next - gs[i]);
  }
  const int r0 = static_cast<int>(std::ceil(start)) % n;
  std::rotate(pts.begin(), pts.begin() + r0, pts.end());
  pts.push_back(pts.front());
  for (auto& r : passes) {
    r.gmin = std::fmod(r.gmin - r0 + n, static_cast<double>(n));
    r.gmax = std::fmod(r.gmax - r0 + n, static_cast<double>(n));
  }
}

// The end of the chain of items (sorted by value) that starts at s: each within tol of the one
// before.
size_t chain_end(const std::vector<AxisValue>& items, size_t s, double tol) {
  size_t e = s + 1;
  while (e < items.size() && items[e].value - items[e - 1].value <= tol) ++e;
  return e;
}

// The value that the group items[s, e) of nearby coordinates aligns to: the fixed one when the
// group has one, else the junctions' mean; none when the group holds nothing to move, a single
// value, or two different fixed values.
std::optional<double> group_target(const std::vector<AxisValue>& items, size_t s, size_t e) {
  std::set<double> fixed_values;
  double sum = 0;
  int movable = 0;
  for (size_t i = s; i < e; ++i) {
    if (items[i].junction < 0)
      fixed_values.insert(items[i].value);
    else
      sum += items[i].value, ++movable;
  }
  if (movable > 0 && e - s >= 2 && fixed_values.size() <= 1)
    return fixed_values.empty() ? sum / movable : *fixed_values.begin();
  return std::nullopt;
}

}  // namespace

// Step 3: crossings between creases become junctions at exact shared vertices.
void Cleaner::make_junctions() {
  std::vector<CreaseEvent> events = crossing_events();
  if (events.empty()) return;
  add_free_end_events(events);
  std::vector<Vec2> pts;
  for (const auto& e : events) pts.push_back(e.point);

  std::vector<std::vector<JunctionPass>> passes(creases_.size());
  const std::vector<std::vector<double>> arc = crease_arc_lengths(creases_);
  for (const auto& cluster : cluster_points(pts, merge_tol_))
    merge_into_junction(cluster, events, arc, passes);
  for (size_t k = 0; k < creases_.size(); ++k) {
    if (passes[k].empty()) continue;
    reroute_through_junctions(static_cast<int>(k), passes[k]);
  }
  merge_shared_segments();
  drop_degenerate_creases();
}

// Two creases that cross at small angles near a junction can come out of rerouting running along
// each other from their own crossing to that junction (each passes both). The two junctions are
// one crowded crossing: the shorter such stretches (up to snap_tol) collapse onto their end with
// more creases through it.
void Cleaner::merge_shared_segments() {
  for (bool merged = true; merged;) {
    merged = false;
    std::map<std::pair<std::pair<double, double>, std::pair<double, double>>, int> uses;
    for (const auto& c : creases_) {
      const int m = segment_count(c.points, c.closed);
      for (int i = 0; i < m; ++i) {
        std::pair<double, double> a{c.points[i].x(), c.points[i].y()};
        std::pair<double, double> b{c.points[(i + 1) % c.points.size()].x(),
                                    c.points[(i + 1) % c.points.size()].y()};
        ++uses[{std::min(a, b), std::max(a, b)}];
      }
    }
    const VertexCounts counts = vertex_counts();
    for (const auto& [segment, n] : uses) {
      const Vec2 a(segment.first.first, segment.first.second);
      const Vec2 b(segment.second.first, segment.second.second);
      if (n < 2 || (a - b).norm() > snap_tol_ || sheet_side(a) != 1 || sheet_side(b) != 1) continue;
      const bool keep_a = counts.at(segment.first) >= counts.at(segment.second);
      const Vec2 from = keep_a ? b : a, to = keep_a ? a : b;
      log("junctions " + format_point(from) + " and " + format_point(to) +
          " merged: creases ran along each other between them");
      replace_vertex(from, to);
      for (auto& c : creases_) {
        c.points.erase(std::unique(c.points.begin(), c.points.end()), c.points.end());
        if (c.closed && c.points.size() > 1 && c.points.front() == c.points.back())
          c.points.pop_back();
      }
      merged = true;
      break;
    }
  }
}

// Two events (one on each crease) per contact between two creases. Throws for creases that
// overlap along a stretch.
std::vector<CreaseEvent> Cleaner::crossing_events() const {
  std::vector<const Polyline2*> polys;
  std::vector<bool> closed;
  for (const auto& c : creases_) polys.push_back(&c.points), closed.push_back(c.closed);
  std::vector<CreaseEvent> events;
  for (const auto& c : find_segment_contacts(polys, closed)) {
    const Polyline2& pa = creases_[c.a].points;
    const Polyline2& pb = creases_[c.b].points;
    const Vec2 &a0 = pa[c.sa], &a1 = pa[(c.sa + 1) % pa.size()];
    const Vec2 &b0 = pb[c.sb], &b1 = pb[(c.sb + 1) % pb.size()];
    if (collinear_overlap(a0, a1, b0, b1))
      throw InputError(name(c.b) + " and " + name(c.a) + " overlap near " +
                       format_point(0.5 * (a0 + a1)) +
                       "; creases may cross or meet but not run along each other");
    const Vec2 p = contact_point(a0, a1, b0, b1);
    events.push_back({p, c.a, c.sa + param_on(p, a0, a1), false});
    events.push_back({p, c.b, c.sb + param_on(p, b0, b1), false});
  }
  return events;
}

// Crease ends off the boundary: near a crossing they merge into its junction.
void Cleaner::add_free_end_events(std::vector<CreaseEvent>& events) const {
  for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
    const Crease& c = creases_[k];
    if (c.closed) continue;
    if (sheet_side(c.points.front()) != 0) events.push_back({c.points.front(), k, 0.0, true});
    if (sheet_side(c.points.back()) != 0)
      events.push_back({c.points.back(), k, static_cast<double>(c.points.size() - 1), true});
  }
}

// Makes one junction of a cluster of nearby events that holds a crossing: at the mean of its
// crossings, with one pass per run of nearby parameters of each crease through it.
void Cleaner::merge_into_junction(const std::vector<int>& cluster,
                                  const std::vector<CreaseEvent>& events,
                                  const std::vector<std::vector<double>>& arc,
                                  std::vector<std::vector<JunctionPass>>& passes) {
  std::vector<Vec2> crossings;
  for (int i : cluster)
    if (!events[i].is_end) crossings.push_back(events[i].point);
  if (crossings.empty()) return;
  const Vec2 junction = mean_of_distinct(crossings);
  std::map<int, std::vector<double>> by_crease;
  for (int i : cluster) by_crease[events[i].crease].push_back(events[i].g);
  for (auto& [k, gs] : by_crease) {
    std::sort(gs.begin(), gs.end());
    // One pass of the crease through the junction region per run of nearby parameters.
    double start = gs[0];
    for (size_t i = 1; i <= gs.size(); ++i) {
      if (i == gs.size() || arc_at(arc[k], gs[i]) - arc_at(arc[k], gs[i - 1]) > 4 * merge_tol_) {
        passes[k].push_back({start, gs[i - 1], junction});
        if (i < gs.size()) start = gs[i];
      }
    }
  }
  if (mean_of_distinct(crossings) != crossings.front() || cluster.size() > crossings.size())
    log("crossings and ends near " + format_point(junction) + " merged into one junction");
}

// Replaces the part of crease k inside each of its junction passes by the junction point.
// Throws when two passes overlap.
void Cleaner::reroute_through_junctions(int k, std::vector<JunctionPass> passes) {
  Crease& c = creases_[k];
  Polyline2 pts = c.points;
  if (c.closed) open_loop_between_passes(pts, passes);
  std::sort(passes.begin(), passes.end(),
            [](const auto& a, const auto& b) { return a.gmin < b.gmin; });
  for (size_t i = 1; i < passes.size(); ++i)
    if (passes[i].gmin < passes[i - 1].gmax)
      throw InputError(name(k) + ": crossings near " + format_point(passes[i].junction) + " and " +
                       format_point(passes[i - 1].junction) +
                       " are too close to separate; move the creases apart");
  const int last = static_cast<int>(pts.size()) - 1;
  Polyline2 out;
  double cur = 0;
  if (passes.front().gmin > 0) out.push_back(pts[0]);
  for (const auto& r : passes) {
    for (int v = static_cast<int>(std::floor(cur)) + 1; v < r.gmin; ++v) out.push_back(pts[v]);
    if (out.empty() || out.back() != r.junction) out.push_back(r.junction);
    cur = r.gmax;
  }
  for (int v = static_cast<int>(std::floor(cur)) + 1; v <= last; ++v) out.push_back(pts[v]);
  out.erase(std::unique(out.begin(), out.end()), out.end());
  if (c.closed && out.size() > 1 && out.front() == out.back()) out.pop_back();
  c.points = std::move(out);
}

// Removes creases that rerouting collapsed to fewer than two (closed: three) points.
void Cleaner::drop_degenerate_creases() {
  creases_.erase(std::remove_if(creases_.begin(), creases_.end(),
                                [](const Crease& c) {
                                  return c.points.size() < 2 || (c.closed && c.points.size() < 3);
                                }),
                 creases_.end());
}

// Step 5: junctions and pins; align nearby junction coordinates.
void Cleaner::align_junctions() {
  for (int axis = 0; axis < 2; ++axis) align_boundary_ends(axis);
  std::vector<Vec2> fixed = collect_junctions();
  for (int axis = 0; axis < 2; ++axis) align_axis(axis, fixed, snap_tol_);
  // Where a group's move was refused, coordinates a hair apart would each pin a grid line a hair
  // from the other's: they align among themselves, in groups within kHairFraction L, then (where
  // such a group is refused too) within kCornerFraction L.
  for (const double fraction : {kHairFraction, kCornerFraction})
    for (int axis = 0; axis < 2; ++axis) align_axis(axis, fixed, fraction * size_);
  pins_ = junctions_;
  pins_.insert(pins_.end(), fixed.begin(), fixed.end());
}

// Sets junctions_ to the interior crease vertices shared by creases; returns the crease ends on
// the boundary off the sheet's bounding box (they must be grid vertices and do not move).
std::vector<Vec2> Cleaner::collect_junctions() {
  const Box2& b = sheet_.bbox;
  std::vector<Vec2> fixed;
  for (const auto& [key, count] : vertex_counts()) {
    const Vec2 q(key.first, key.second);
    const int side = sheet_side(q);
    if (side == 1 && count >= 2) junctions_.push_back(q);
    if (side == 0 && q.x() != b.xmin && q.x() != b.xmax && q.y() != b.ymin && q.y() != b.ymax)
      fixed.push_back(q);
  }
  return fixed;
}

// Crease ends on the boundary whose `axis` coordinates differ by a hair (all within kHairFraction
// L of the smallest), as in drawings whose vertices were rounded independently, move to
// their mean: each would otherwise pin its own grid line beside the others'. Ends a hair from the
// bounding box (within kCornerFraction L: a boundary drawn with a small jog) move onto it, where
// the grid has its outer line.
void Cleaner::align_boundary_ends(int axis) {
  const Box2& b = sheet_.bbox;
  std::set<std::pair<double, double>> seen;
  std::vector<Vec2> ends;
  for (const auto& c : creases_) {
    if (c.closed) continue;
    for (const Vec2& q : {c.points.front(), c.points.back()})
      if (sheet_side(q) == 0 && q.x() != b.xmin && q.x() != b.xmax && q.y() != b.ymin &&
          q.y() != b.ymax && seen.insert({q.x(), q.y()}).second)
        ends.push_back(q);
  }
  const double tol = kCornerFraction * size_;
  const double lo = axis == 0 ? b.xmin : b.ymin, hi = axis == 0 ? b.xmax : b.ymax;
  std::vector<Vec2> inner;
  for (const Vec2& q : ends) {
    if (q[axis] - lo <= tol)
      move_boundary_end(q, axis, lo);
    else if (hi - q[axis] <= tol)
      move_boundary_end(q, axis, hi);
    else
      inner.push_back(q);
  }
  ends = std::move(inner);
  std::sort(ends.begin(), ends.end(),
            [axis](const Vec2& p, const Vec2& q) { return p[axis] < q[axis]; });
  for (size_t s = 0; s < ends.size();) {
    size_t e = s + 1;
    while (e < ends.size() && ends[e][axis] - ends[s][axis] <= kHairFraction * size_) ++e;
    if (ends[e - 1][axis] != ends[s][axis]) {
      double target = 0;
      for (size_t i = s; i < e; ++i) target += ends[i][axis] / static_cast<double>(e - s);
      for (size_t i = s; i < e; ++i) move_boundary_end(ends[i], axis, target);
    }
    s = e;
  }
}

// Moves the crease end `end` on the boundary to `axis` coordinate `target`, in the creases and the
// boundary loops.
void Cleaner::move_boundary_end(const Vec2& end, int axis, double target) {
  const Vec2 moved = with_coordinate(end, axis, target);
  log("boundary point " + format_point(end) + " aligned in " + (axis == 0 ? "x" : "y") + " to " +
      format_number(target));
  replace_vertex(end, moved);
  for (auto& loop : loops_) std::replace(loop.begin(), loop.end(), end, moved);
}

// Aligns the `axis` coordinates of junctions that lie within tol of each other (in chains).
void Cleaner::align_axis(int axis, std::vector<Vec2>& fixed, double tol) {
  std::vector<AxisValue> items;
  for (size_t j = 0; j < junctions_.size(); ++j)
    items.push_back({junctions_[j][axis], static_cast<int>(j)});
  for (size_t k = 0; k < fixed.size(); ++k)
    items.push_back({fixed[k][axis], -1 - static_cast<int>(k)});
  std::sort(items.begin(), items.end(),
            [](const AxisValue& x, const AxisValue& y) { return x.value < y.value; });
  for (size_t s = 0, e; s < items.size(); s = e) {
    e = chain_end(items, s, tol);
    align_group({items.begin() + s, items.begin() + e}, axis, fixed);
  }
}

// Aligns one group of nearby `axis` coordinates (see group_target). Where some junctions cannot
// reach the group's fixed line but all reach their own mean, a hair (kCornerFraction L) from
// it, the fixed end moves there instead, boundary vertex and all. Junctions that still cannot
// reach the target and lie a hair apart align among themselves, or each would pin a grid line a
// hair from the others'.
void Cleaner::align_group(const std::vector<AxisValue>& group, int axis, std::vector<Vec2>& fixed) {
  std::optional<double> target = group_target(group, 0, group.size());
  if (!target) return;
  std::vector<AxisValue> junctions;
  std::vector<Vec2*> ends;
  for (const AxisValue& g : group)
    if (g.junction >= 0)
      junctions.push_back(g);
    else
      ends.push_back(&fixed[-1 - g.junction]);
  const double mean = group_target(junctions, 0, junctions.size()).value_or(junctions[0].value);
  auto all_reach = [&](double t) {
    return std::all_of(junctions.begin(), junctions.end(), [&](const AxisValue& g) {
      return g.value == t || can_align_junction(g.junction, axis, t);
    });
  };
  auto ends_reach = [&](double t) {
    return std::all_of(ends.begin(), ends.end(), [&](const Vec2* q) {
      return std::abs(t - (*q)[axis]) <= kCornerFraction * size_ &&
             move_keeps_creases_apart(*q, with_coordinate(*q, axis, t));
    });
  };
  if (!ends.empty() && !all_reach(*target) && all_reach(mean) && ends_reach(mean)) {
    for (Vec2* q : ends) {
      move_boundary_end(*q, axis, mean);
      (*q)[axis] = mean;
    }
    target = mean;
  }
  std::vector<AxisValue> refused;
  for (const AxisValue& g : junctions)
    if (g.value != *target && !align_junction(g.junction, axis, *target)) refused.push_back(g);
  // A hair apart: in chains within kCornerFraction L (a wide group's refused junctions stay).
  for (size_t s = 0, e; s < refused.size(); s = e) {
    e = chain_end(refused, s, kCornerFraction * size_);
    if (const auto own = group_target(refused, s, e))
      for (size_t i = s; i < e; ++i)
        if (refused[i].value != *own) align_junction(refused[i].junction, axis, *own);
  }
}

// Moves junction j's `axis` coordinate to `target` (in every crease), unless another junction
// is already there or the creases through it would then cross others (in dense drawings the move
// can reach past a neighbouring crease); returns whether it moved.
bool Cleaner::align_junction(int j, int axis, double target) {
  if (!can_align_junction(j, axis, target)) return false;
  Vec2& jpt = junctions_[j];
  const Vec2 moved = with_coordinate(jpt, axis, target);
  log(std::string("junction ") + format_point(jpt) + " aligned in " + (axis == 0 ? "x" : "y") +
      " to " + format_number(target));
  replace_vertex(jpt, moved);
  jpt = moved;
  return true;
}

}  // namespace sdog::cleaning

namespace sdog::cleaning {

// Can junction j move to `axis` coordinate `target` (see align_junction)?
bool Cleaner::can_align_junction(int j, int axis, double target) const {
  const Vec2 moved = with_coordinate(junctions_[j], axis, target);
  return std::find(junctions_.begin(), junctions_.end(), moved) == junctions_.end() &&
         move_keeps_creases_apart(junctions_[j], moved);
}

// Would the crease segments at vertex `from`, moved to `to` (with the boundary when `from` is a
// boundary vertex), stay clear of every other crease and boundary segment (touching only at
// shared vertices)?
bool Cleaner::move_keeps_creases_apart(const Vec2& from, const Vec2& to) const {
  auto moved = [&](const Vec2& p) { return p == from ? to : p; };
  std::vector<std::pair<Vec2, Vec2>> changed, others;
  for (const auto& c : creases_) {
    const int m = segment_count(c.points, c.closed);
    for (int i = 0; i < m; ++i) {
      const Vec2 &a = c.points[i], &b = c.points[(i + 1) % c.points.size()];
      (a == from || b == from ? changed : others).push_back({moved(a), moved(b)});
    }
  }
  for (const auto& loop : loops_)
    for (size_t i = 0; i < loop.size(); ++i)
      others.push_back({moved(loop[i]), moved(loop[(i + 1) % loop.size()])});
  for (const auto& [a, b] : changed)
    for (const auto& [c, d] : others) {
      const bool shared = a == c || a == d || b == c || b == d;
      if (segments_intersect(a, b, c, d) && (!shared || collinear_overlap(a, b, c, d)))
        return false;
    }
  return true;
}

}  // namespace sdog::cleaning
