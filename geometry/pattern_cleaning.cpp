#include "geometry/pattern_cleaning.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

#include "base/errors.h"
#include "geometry/plane_geometry.h"
#include "base/text_format.h"

namespace sdog {

std::string CleaningOptions::validate() const {
  if (!(merge_fraction >= 0 && merge_fraction < 0.25))
    return "merge_fraction must be in [0, 0.25), got " + format_number(merge_fraction);
  if (!(snap_fraction >= 0 && snap_fraction < 0.25))
    return "snap_fraction must be in [0, 0.25), got " + format_number(snap_fraction);
  return "";
}

namespace {

using Vec2 = Eigen::Vector2d;

struct Insertion {
  int seg;
  double param;
  Vec2 point;
};

// Inserts points into polyline segments (point `param` along segment `seg`), skipping points
// equal to a neighbouring vertex.
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

// Single-linkage clusters of points closer than tol (bucket hashing, union-find).
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

class Cleaner {
 public:
  Cleaner(const CreasePattern& pattern, const CleaningOptions& options)
      : source_(pattern.source), sheet_(pattern.sheet), creases_(pattern.creases) {
    const double L = pattern.size();
    merge_tol_ = options.merge_fraction * L;
    snap_tol_ = options.snap_fraction * L;
    loops_.push_back(sheet_.outer);
    for (const auto& h : sheet_.holes) loops_.push_back(h);
    for (size_t k = 0; k < creases_.size(); ++k) names_.push_back(creases_[k].origin);
  }

  CleanPattern run() {
    merge_crease_ends();
    join_continuing_creases();
    clip_to_sheet();
    make_junctions();
    snap_free_ends();
    align_junctions();
    verify();
    CleanPattern out;
    out.source = source_;
    out.sheet = sheet_;
    out.sheet.outer = loops_[0];
    out.sheet.holes.assign(loops_.begin() + 1, loops_.end());
    out.creases = creases_;
    out.junctions = junctions_;
    out.pins = pins_;
    out.changes = changes_;
    return out;
  }

 private:
  // +1 inside the sheet, 0 on its boundary, -1 outside (or in a hole).
  int sheet_side(const Vec2& p) const {
    const int outer = point_in_polygon(p, loops_[0]);
    if (outer <= 0) return outer;
    for (size_t h = 1; h < loops_.size(); ++h) {
      const int r = point_in_polygon(p, loops_[h]);
      if (r == 0) return 0;
      if (r == 1) return -1;
    }
    return 1;
  }

  std::string name(int k) const {
    return "crease " + std::to_string(k) + " (" + creases_[k].origin + ")";
  }

  static Vec2& end_point(Crease& c, int end) {
    return end == 0 ? c.points.front() : c.points.back();
  }

  void log(const std::string& s) { changes_.push_back(s); }

  // Step 1: crease ends closer than merge_tol meet at one point.
  void merge_crease_ends() {
    std::vector<Vec2> pts;
    std::vector<std::pair<int, int>> refs;
    for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
      if (creases_[k].closed) continue;
      for (int e = 0; e < 2; ++e) {
        pts.push_back(end_point(creases_[k], e));
        refs.push_back({k, e});
      }
    }
    for (const auto& cluster : cluster_points(pts, merge_tol_)) {
      if (cluster.size() < 2) continue;
      std::vector<Vec2> members;
      for (int i : cluster) members.push_back(pts[i]);
      Vec2 target = mean_of_distinct(members);
      for (const auto& p : members)
        if (sheet_side(p) == 0) target = p;  // keep ends that are exactly on the boundary there
      bool moved = false;
      for (int i : cluster) {
        Vec2& p = end_point(creases_[refs[i].first], refs[i].second);
        if (p != target) moved = true;
        p = target;
      }
      if (moved)
        log(std::to_string(cluster.size()) + " crease ends merged at " + format_point(target));
    }
  }

  // Two crease ends meeting alone inside the sheet are one crease drawn in two pieces.
  void join_continuing_creases() {
    for (bool joined = true; joined;) {
      joined = false;
      std::map<std::pair<double, double>, std::vector<std::pair<int, int>>> ends;
      for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
        if (creases_[k].closed) continue;
        for (int e = 0; e < 2; ++e) {
          const Vec2& p = end_point(creases_[k], e);
          ends[{p.x(), p.y()}].push_back({k, e});
        }
      }
      for (const auto& [key, list] : ends) {
        if (list.size() != 2) continue;
        const Vec2 p(key.first, key.second);
        if (sheet_side(p) != 1 || on_other_crease(p, list[0].first, list[1].first)) continue;
        const auto [a, ea] = list[0];
        const auto [b, eb] = list[1];
        if (creases_[a].dashed != creases_[b].dashed) continue;
        if (a == b) {
          creases_[a].closed = true;
          creases_[a].points.pop_back();
          log(name(a) + " closes on itself at " + format_point(p));
        } else {
          Polyline2 first = creases_[a].points, second = creases_[b].points;
          if (ea == 0) std::reverse(first.begin(), first.end());
          if (eb == 1) std::reverse(second.begin(), second.end());
          first.insert(first.end(), second.begin() + 1, second.end());
          log(name(b) + " continues " + name(a) + " at " + format_point(p) + "; joined");
          creases_[a].points = std::move(first);
          creases_.erase(creases_.begin() + b);
        }
        joined = true;
        break;
      }
    }
  }

  bool on_other_crease(const Vec2& p, int a, int b) const {
    for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
      if (k == a || k == b) continue;
      const auto& pts = creases_[k].points;
      for (int i = 0; i < segment_count(pts, creases_[k].closed); ++i)
        if (segments_intersect(p, p, pts[i], pts[(i + 1) % pts.size()])) return true;
    }
    return false;
  }

  // The contact point of two intersecting segments [a0,a1] and [b0,b1] (not collinear).
  static Vec2 contact_point(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
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

  static bool collinear_overlap(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
    if (orientation(b0, b1, a0) != 0 || orientation(b0, b1, a1) != 0) return false;
    // Collinear and intersecting: an overlap unless they only share an end.
    const Vec2 d = a1 - a0;
    const double t0 = param_raw(b0, a0, d), t1 = param_raw(b1, a0, d);
    return std::min(1.0, std::max(t0, t1)) > std::max(0.0, std::min(t0, t1));
  }
  static double param_raw(const Vec2& p, const Vec2& a, const Vec2& d) {
    return (p - a).dot(d) / d.squaredNorm();
  }

  // Step 2: clip creases to the sheet.
  void clip_to_sheet() {
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

    std::vector<Crease> kept;
    std::vector<std::string> kept_names;
    for (int k = 0; k < nc; ++k) {
      Crease& crease = creases_[k];
      if (crease_events[k].empty()) {
        if (sheet_side(crease.points.front()) == 1) {
          kept.push_back(crease);
        } else {
          log(name(k) + " lies outside the sheet; removed");
        }
        continue;
      }
      std::set<std::pair<double, double>> cuts;
      for (const auto& e : crease_events[k]) cuts.insert({e.point.x(), e.point.y()});
      Polyline2 pts = with_insertions(crease.points, crease.closed, crease_events[k]);
      if (crease.closed) {
        // Start the loop at a cut so that it splits like an open curve.
        auto it = std::find_if(pts.begin(), pts.end(), [&](const Vec2& p) {
          return cuts.count({p.x(), p.y()}) > 0;
        });
        std::rotate(pts.begin(), it, pts.end());
        pts.push_back(pts.front());
      }
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
    creases_ = std::move(kept);
  }

  // Step 3: crossings between creases become junctions at exact shared vertices.
  void make_junctions() {
    struct Event {
      Vec2 point;
      int crease;
      double g;  // global parameter: segment index + parameter on the segment
      bool is_end;
    };
    std::vector<const Polyline2*> polys;
    std::vector<bool> closed;
    for (const auto& c : creases_) polys.push_back(&c.points), closed.push_back(c.closed);
    std::vector<Event> events;
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
    if (events.empty()) return;
    for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
      const Crease& c = creases_[k];
      if (c.closed) continue;
      if (sheet_side(c.points.front()) != 0) events.push_back({c.points.front(), k, 0.0, true});
      if (sheet_side(c.points.back()) != 0)
        events.push_back({c.points.back(), k, static_cast<double>(c.points.size() - 1), true});
    }
    std::vector<Vec2> pts;
    for (const auto& e : events) pts.push_back(e.point);

    struct Replacement {
      double gmin, gmax;
      Vec2 junction;
    };
    std::vector<std::vector<Replacement>> replacements(creases_.size());
    std::vector<std::vector<double>> arc(creases_.size());
    for (size_t k = 0; k < creases_.size(); ++k) {
      const auto& p = creases_[k].points;
      const int m = segment_count(p, creases_[k].closed);
      arc[k].assign(1, 0.0);
      for (int i = 0; i < m; ++i)
        arc[k].push_back(arc[k].back() + (p[(i + 1) % p.size()] - p[i]).norm());
    }
    auto arc_at = [&](int k, double g) {
      const int i = std::min(static_cast<int>(g), static_cast<int>(arc[k].size()) - 2);
      return arc[k][i] + (g - i) * (arc[k][i + 1] - arc[k][i]);
    };
    for (const auto& cluster : cluster_points(pts, merge_tol_)) {
      std::vector<Vec2> crossings;
      for (int i : cluster)
        if (!events[i].is_end) crossings.push_back(events[i].point);
      if (crossings.empty()) continue;
      const Vec2 junction = mean_of_distinct(crossings);
      std::map<int, std::vector<double>> by_crease;
      for (int i : cluster) by_crease[events[i].crease].push_back(events[i].g);
      for (auto& [k, gs] : by_crease) {
        std::sort(gs.begin(), gs.end());
        // One pass of the crease through the junction region per run of nearby parameters.
        double start = gs[0];
        for (size_t i = 1; i <= gs.size(); ++i) {
          if (i == gs.size() || arc_at(k, gs[i]) - arc_at(k, gs[i - 1]) > 4 * merge_tol_) {
            replacements[k].push_back({start, gs[i - 1], junction});
            if (i < gs.size()) start = gs[i];
          }
        }
      }
      if (mean_of_distinct(crossings) != crossings.front() || cluster.size() > crossings.size())
        log("crossings and ends near " + format_point(junction) + " merged into one junction");
    }
    for (size_t k = 0; k < creases_.size(); ++k) {
      if (replacements[k].empty()) continue;
      apply_replacements(static_cast<int>(k), replacements[k]);
    }
    creases_.erase(std::remove_if(creases_.begin(), creases_.end(),
                                  [](const Crease& c) {
                                    return c.points.size() < 2 || (c.closed && c.points.size() < 3);
                                  }),
                   creases_.end());
  }

  template <class Replacement>
  void apply_replacements(int k, std::vector<Replacement> reps) {
    Crease& c = creases_[k];
    Polyline2 pts = c.points;
    const int n = static_cast<int>(pts.size());
    if (c.closed) {
      // Rotate the loop to start in the middle of the largest gap between junction passes, then
      // treat it as an open curve that returns to its start.
      std::vector<double> gs;
      for (const auto& r : reps) gs.push_back(r.gmin), gs.push_back(r.gmax);
      std::sort(gs.begin(), gs.end());
      double best_gap = -1, start = 0;
      for (size_t i = 0; i < gs.size(); ++i) {
        const double next = i + 1 < gs.size() ? gs[i + 1] : gs[0] + n;
        if (next - gs[i] > best_gap) best_gap = next - gs[i], start = gs[i] + 0.5 * (next - gs[i]);
      }
      const int r0 = static_cast<int>(std::ceil(start)) % n;
      std::rotate(pts.begin(), pts.begin() + r0, pts.end());
      pts.push_back(pts.front());
      for (auto& r : reps) {
        r.gmin = std::fmod(r.gmin - r0 + n, static_cast<double>(n));
        r.gmax = std::fmod(r.gmax - r0 + n, static_cast<double>(n));
      }
    }
    std::sort(reps.begin(), reps.end(),
              [](const auto& a, const auto& b) { return a.gmin < b.gmin; });
    for (size_t i = 1; i < reps.size(); ++i)
      if (reps[i].gmin < reps[i - 1].gmax)
        throw InputError(name(k) + ": crossings near " + format_point(reps[i].junction) + " and " +
                         format_point(reps[i - 1].junction) +
                         " are too close to separate; move the creases apart");
    const int last = static_cast<int>(pts.size()) - 1;
    Polyline2 out;
    double cur = 0;
    if (reps.front().gmin > 0) out.push_back(pts[0]);
    for (const auto& r : reps) {
      for (int v = static_cast<int>(std::floor(cur)) + 1; v < r.gmin; ++v) out.push_back(pts[v]);
      if (out.empty() || out.back() != r.junction) out.push_back(r.junction);
      cur = r.gmax;
    }
    for (int v = static_cast<int>(std::floor(cur)) + 1; v <= last; ++v) out.push_back(pts[v]);
    out.erase(std::unique(out.begin(), out.end()), out.end());
    if (c.closed && out.size() > 1 && out.front() == out.back()) out.pop_back();
    c.points = std::move(out);
  }

  // How often each point occurs as a crease vertex.
  std::map<std::pair<double, double>, int> vertex_counts() const {
    std::map<std::pair<double, double>, int> counts;
    for (const auto& c : creases_)
      for (const auto& p : c.points) ++counts[{p.x(), p.y()}];
    return counts;
  }

  // Step 4: free crease ends snap to a crease vertex, the boundary or a crease.
  void snap_free_ends() {
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

  void snap_end(int k, int e, const std::map<std::pair<double, double>, int>& counts) {
    const Vec2 p = end_point(creases_[k], e);
    // (a) crease vertices: junctions and boundary ends of other creases.
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
      return;
    }
    // (b) the boundary.
    double best_bnd = INFINITY;
    int loop = -1, seg = -1;
    double seg_param = 0;
    Vec2 on_bnd;
    for (size_t l = 0; l < loops_.size(); ++l) {
      const Polyline2& lp = loops_[l];
      for (size_t i = 0; i < lp.size(); ++i) {
        double s;
        const Vec2 q = closest_point_on_segment(p, lp[i], lp[(i + 1) % lp.size()], &s);
        if ((q - p).norm() < best_bnd)
          best_bnd = (q - p).norm(), loop = static_cast<int>(l), seg = static_cast<int>(i),
          seg_param = s, on_bnd = q;
      }
    }
    if (best_bnd <= snap_tol_) {
      const Polyline2& lp = loops_[loop];
      const Vec2 &b0 = lp[seg], &b1 = lp[(seg + 1) % lp.size()];
      if (b0.y() == b1.y()) on_bnd.y() = b0.y();
      if (b0.x() == b1.x()) on_bnd.x() = b0.x();
      loops_[loop] = with_insertions(lp, true, {{seg, seg_param, on_bnd}});
      end_point(creases_[k], e) = on_bnd;
      log(name(k) + ": end " + format_point(p) + " moved onto the sheet boundary at " +
          format_point(on_bnd));
      return;
    }
    // (c) another crease (a T junction); the crease itself counts away from this end.
    double best_crease = INFINITY;
    int other = -1, oseg = -1;
    double oparam = 0;
    Vec2 on_crease;
    for (int j = 0; j < static_cast<int>(creases_.size()); ++j) {
      const Polyline2& cp = creases_[j].points;
      const int m = segment_count(cp, creases_[j].closed);
      double along = 0;  // arc length from this end, for the crease itself
      for (int i = 0; i < m; ++i) {
        const int idx = (j == k && e == 1) ? m - 1 - i : i;
        Vec2 a = cp[idx], b = cp[(idx + 1) % cp.size()];
        if (j == k) {
          // Skip the part of the crease within 3 snap_tol of this end (it is the end itself).
          const double len = (b - a).norm(), limit = 3 * snap_tol_;
          along += len;
          if (along <= limit) continue;
          const double cut = (limit - (along - len)) / len;  // fraction of the segment to skip
          if (cut > 0) {
            if (e == 1)
              b = b + cut * (a - b);
            else
              a = a + cut * (b - a);
          }
        }
        double s;
        const Vec2 q = closest_point_on_segment(p, a, b, &s);
        if ((q - p).norm() < best_crease) {
          best_crease = (q - p).norm();
          other = j;
          oseg = idx;
          oparam = param_on(q, cp[idx], cp[(idx + 1) % cp.size()]);
          on_crease = q;
        }
      }
    }
    if (best_crease <= snap_tol_) {
      Crease& oc = creases_[other];
      oc.points = with_insertions(oc.points, oc.closed, {{oseg, oparam, on_crease}});
      end_point(creases_[k], e) = on_crease;
      log(name(k) + ": end " + format_point(p) + " joined " + name(other) + " at " +
          format_point(on_crease));
      return;
    }
    throw InputError(name(k) + " ends at " + format_point(p) + ", " + format_number(best_bnd) +
                     " units from the sheet boundary" +
                     (std::isfinite(best_crease)
                          ? " and " + format_number(best_crease) + " from the nearest crease"
                          : std::string()) +
                     "; creases must end on the boundary or on another crease (tolerance " +
                     format_number(snap_tol_) + " = L/50)");
  }

  bool is_boundary_end(const Vec2& q, int except) const {
    for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
      if (k == except || creases_[k].closed) continue;
      const auto& c = creases_[k].points;
      if ((c.front() == q || c.back() == q) && sheet_side(q) == 0) return true;
    }
    return false;
  }

  void replace_vertex(const Vec2& from, const Vec2& to) {
    for (auto& c : creases_)
      for (auto& p : c.points)
        if (p == from) p = to;
  }

  // Step 5: junctions and pins; align nearby junction coordinates.
  void align_junctions() {
    const Box2& b = sheet_.bbox;
    std::vector<Vec2> fixed;
    for (const auto& [key, count] : vertex_counts()) {
      const Vec2 q(key.first, key.second);
      const int side = sheet_side(q);
      if (side == 1 && count >= 2) junctions_.push_back(q);
      if (side == 0 && q.x() != b.xmin && q.x() != b.xmax && q.y() != b.ymin && q.y() != b.ymax)
        fixed.push_back(q);
    }
    for (int axis = 0; axis < 2; ++axis) {
      struct Item {
        double value;
        int junction;  // -1 for a fixed boundary end
      };
      std::vector<Item> items;
      for (size_t j = 0; j < junctions_.size(); ++j)
        items.push_back({junctions_[j][axis], static_cast<int>(j)});
      for (const auto& f : fixed) items.push_back({f[axis], -1});
      std::sort(items.begin(), items.end(),
                [](const Item& x, const Item& y) { return x.value < y.value; });
      for (size_t s = 0; s < items.size();) {
        size_t e = s + 1;
        while (e < items.size() && items[e].value - items[e - 1].value <= snap_tol_) ++e;
        std::set<double> fixed_values;
        double sum = 0;
        int movable = 0;
        for (size_t i = s; i < e; ++i) {
          if (items[i].junction < 0)
            fixed_values.insert(items[i].value);
          else
            sum += items[i].value, ++movable;
        }
        if (movable > 0 && e - s >= 2 && fixed_values.size() <= 1) {
          const double target = fixed_values.empty() ? sum / movable : *fixed_values.begin();
          for (size_t i = s; i < e; ++i) {
            if (items[i].junction < 0 || items[i].value == target) continue;
            Vec2& jpt = junctions_[items[i].junction];
            Vec2 moved = jpt;
            moved[axis] = target;
            if (std::find(junctions_.begin(), junctions_.end(), moved) != junctions_.end())
              continue;
            log(std::string("junction ") + format_point(jpt) + " aligned in " +
                (axis == 0 ? "x" : "y") + " to " + format_number(target));
            replace_vertex(jpt, moved);
            jpt = moved;
          }
        }
        s = e;
      }
    }
    pins_ = junctions_;
    pins_.insert(pins_.end(), fixed.begin(), fixed.end());
  }

  // Step 6: creases must meet each other and the boundary only at shared vertices.
  void verify() const {
    const int nc = static_cast<int>(creases_.size());
    std::vector<const Polyline2*> polys;
    std::vector<bool> closed;
    for (const auto& c : creases_) polys.push_back(&c.points), closed.push_back(c.closed);
    for (const auto& l : loops_) polys.push_back(&l), closed.push_back(true);
    for (const auto& c : find_segment_contacts(polys, closed)) {
      if (c.a >= nc) continue;  // boundary/boundary contacts were checked when reading
      const Polyline2& pa = *polys[c.a];
      const Polyline2& pb = *polys[c.b];
      const Vec2 &a0 = pa[c.sa], &a1 = pa[(c.sa + 1) % pa.size()];
      const Vec2 &b0 = pb[c.sb], &b1 = pb[(c.sb + 1) % pb.size()];
      const bool shared = a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1;
      if (shared && !collinear_overlap(a0, a1, b0, b1)) continue;
      const std::string other = c.b < nc ? name(c.b) : std::string("the sheet boundary");
      throw InputError(name(c.a) + " and " + other + " cross near " +
                       format_point(contact_point(a0, a1, b0, b1)) +
                       " where no junction could be placed; simplify the pattern there");
    }
  }

  std::string source_;
  Sheet sheet_;
  std::vector<Crease> creases_;
  std::vector<std::string> names_;
  std::vector<Polyline2> loops_;
  double merge_tol_ = 0, snap_tol_ = 0;
  std::vector<Vec2> junctions_, pins_;
  std::vector<std::string> changes_;
};

}  // namespace

CleanPattern clean_pattern(const CreasePattern& pattern, const CleaningOptions& options) {
  if (const std::string msg = options.validate(); !msg.empty()) throw UsageError(msg);
  return Cleaner(pattern, options).run();
}

}  // namespace sdog
