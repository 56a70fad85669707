// Pattern cleaning: the options, the pipeline of steps, step 1 (merging and joining crease ends)
// and the final check. The other steps are in cleaning_*.cpp (see cleaner.h).
#include "geometry/pattern/pattern_cleaning.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/pattern/internal/cleaner.h"
#include "geometry/pattern/plane_geometry.h"

namespace sdog {

std::string CleaningOptions::validate() const {
  if (!(merge_fraction >= 0 && merge_fraction < 0.25))
    return "merge_fraction must be in [0, 0.25), got " + format_number(merge_fraction);
  if (!(snap_fraction >= 0 && snap_fraction < 0.25))
    return "snap_fraction must be in [0, 0.25), got " + format_number(snap_fraction);
  return "";
}

namespace cleaning {

Cleaner::Cleaner(const CreasePattern& pattern, const CleaningOptions& options)
    : source_(pattern.source),
      sheet_(pattern.sheet),
      creases_(pattern.creases),
      warnings_(pattern.warnings) {
  const double L = pattern.size();
  size_ = L;
  merge_tol_ = options.merge_fraction * L;
  snap_tol_ = options.snap_fraction * L;
  snap_fraction_ = options.snap_fraction;
  seams_ = options.seams;
  loops_.push_back(sheet_.outer);
  for (const auto& h : sheet_.holes) loops_.push_back(h);
}

CleanPattern Cleaner::run() {
  drop_overlapping_segments(kTouchFraction);
  // Pieces of one crease drawn end to end (curves exported as many short lines) are joined before
  // nearby ends merge, which would otherwise pull a chain of pieces shorter than merge_tol
  // together.
  merge_crease_ends(kTouchFraction * size_);
  join_continuing_creases(touching_pieces());
  move_ends_onto_boundary_corners();
  merge_crease_ends(kCornerFraction * size_);
  merge_crease_ends(merge_tol_);
  // Creases drawn twice with small offsets: their ends coincide now, their segments lie within a
  // hair of each other.
  drop_overlapping_segments(kCornerFraction);
  join_continuing_creases(std::nullopt);
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
  out.warnings = warnings_;
  return out;
}

int Cleaner::sheet_side(const Vec2& p) const {
  const int outer = point_in_polygon(p, loops_[0]);
  if (outer <= 0) return outer;
  for (size_t h = 1; h < loops_.size(); ++h) {
    const int r = point_in_polygon(p, loops_[h]);
    if (r == 0) return 0;
    if (r == 1) return -1;
  }
  return 1;
}

std::string Cleaner::name(int k) const {
  return "crease " + std::to_string(k) + " (" + creases_[k].origin + ")";
}

VertexCounts Cleaner::vertex_counts() const {
  VertexCounts counts;
  for (const auto& c : creases_)
    for (const auto& p : c.points) ++counts[{p.x(), p.y()}];
  return counts;
}

void Cleaner::replace_vertex(const Vec2& from, const Vec2& to) {
  for (auto& c : creases_)
    for (auto& p : c.points)
      if (p == from) p = to;
}

// Step 1: crease ends closer than tol meet at one point.
void Cleaner::merge_crease_ends(double tol) {
  std::vector<Vec2> pts;
  std::vector<std::pair<int, int>> refs;
  for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
    if (creases_[k].closed) continue;
    for (int e = 0; e < 2; ++e) {
      pts.push_back(end_point(creases_[k], e));
      refs.push_back({k, e});
    }
  }
  for (const auto& cluster : cluster_points(pts, tol)) {
    if (cluster.size() < 2) continue;
    std::vector<Vec2> members;
    for (int i : cluster) members.push_back(pts[i]);
    Vec2 target = mean_of_distinct(members);
    // A chain of ends each near the next but spread wider than tol is a dense drawing (a fan of
    // creases, a fine tessellation), not one point drawn sloppily: it stays as drawn.
    if (std::any_of(members.begin(), members.end(),
                    [&](const Vec2& p) { return (p - target).norm() > tol; }))
      continue;
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

// A crease end a hair away from a boundary vertex (a drawing whose boundary and creases were
// exported with slightly different rounding) is moved onto it; left alone, it would become its own
// boundary point beside the vertex and pin a grid line a hair away from the vertex's.
void Cleaner::move_ends_onto_boundary_corners() {
  const double tol = kCornerFraction * size_;
  std::map<std::pair<long long, long long>, std::vector<Vec2>> corners;
  auto cell = [&](double v) { return static_cast<long long>(std::floor(v / tol)); };
  for (const auto& loop : loops_)
    for (const auto& q : loop) corners[{cell(q.x()), cell(q.y())}].push_back(q);
  for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
    if (creases_[k].closed) continue;
    for (int e = 0; e < 2; ++e) {
      Vec2& p = end_point(creases_[k], e);
      const Vec2* nearest = nullptr;
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy) {
          const auto it = corners.find({cell(p.x()) + dx, cell(p.y()) + dy});
          if (it == corners.end()) continue;
          for (const auto& q : it->second)
            if ((q - p).norm() <= tol && (!nearest || (q - p).norm() < (*nearest - p).norm()))
              nearest = &q;
        }
      if (!nearest || *nearest == p) continue;
      log(name(k) + ": end " + format_point(p) + " moved onto the boundary vertex " +
          format_point(*nearest));
      p = *nearest;
    }
  }
}

// The interior points where exactly two crease ends of one assignment touch, in groups (within
// merge_tol, chained) that hold no loose interior crease end (alone, or touching one of another
// assignment; three or more ends at one point are an exact junction, not loose), and not within
// kCornerFraction L of such a junction: the joints of curves drawn as chains of short pieces. A
// joint near a loose end or a junction is left to merging, which makes one junction of them.
std::set<std::pair<double, double>> Cleaner::touching_pieces() const {
  std::map<std::pair<double, double>, std::vector<int>> ends;
  for (int k = 0; k < static_cast<int>(creases_.size()); ++k)
    if (!creases_[k].closed)
      for (const Vec2* p : {&creases_[k].points.front(), &creases_[k].points.back()})
        if (sheet_side(*p) == 1) ends[{p->x(), p->y()}].push_back(k);
  std::vector<Vec2> points;
  std::vector<bool> paired;
  for (const auto& [key, owners] : ends) {
    points.push_back(Vec2(key.first, key.second));
    // Three or more ends at exactly one point are a junction drawn exactly, not a loose end.
    paired.push_back(owners.size() > 2 ||
                     (owners.size() == 2 && creases_[owners[0]].folds_like(creases_[owners[1]])));
  }
  auto owners = [&](int i) { return ends.at({points[i].x(), points[i].y()}); };
  // Does a crease at joint i reach junction j (a short piece between them)?
  auto reaches = [&](int i, int j) {
    for (int k : owners(i))
      for (const Vec2* p : {&creases_[k].points.front(), &creases_[k].points.back()})
        if (*p == points[j]) return true;
    return false;
  };
  std::set<std::pair<double, double>> joints;
  for (const auto& cluster : cluster_points(points, merge_tol_)) {
    if (!std::all_of(cluster.begin(), cluster.end(), [&](int i) { return paired[i]; })) continue;
    for (int i : cluster) {
      // A joint a hair from a junction, not on a piece leading to it, is that junction drawn with
      // an offset: merging makes them one.
      const bool at_junction = std::any_of(cluster.begin(), cluster.end(), [&](int j) {
        return owners(j).size() > 2 && (points[j] - points[i]).norm() <= kCornerFraction * size_ &&
               !reaches(i, j);
      });
      if (owners(i).size() == 2 && !at_junction) joints.insert({points[i].x(), points[i].y()});
    }
  }
  return joints;
}

// Two crease ends meeting alone inside the sheet are one crease drawn in two pieces (only at
// `only`'s points when given).
void Cleaner::join_continuing_creases(
    const std::optional<std::set<std::pair<double, double>>>& only) {
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
      if (list.size() != 2 || (only && !only->count(key))) continue;
      const Vec2 p(key.first, key.second);
      if (sheet_side(p) != 1 || on_other_crease(p, list[0].first, list[1].first)) continue;
      const auto [a, ea] = list[0];
      const auto [b, eb] = list[1];
      if (!creases_[a].folds_like(creases_[b])) continue;
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

bool Cleaner::on_other_crease(const Vec2& p, int a, int b) const {
  for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
    if (k == a || k == b) continue;
    const auto& pts = creases_[k].points;
    for (int i = 0; i < segment_count(pts, creases_[k].closed); ++i)
      if (segments_intersect(p, p, pts[i], pts[(i + 1) % pts.size()])) return true;
  }
  return false;
}

// Step 6: creases must meet each other and the boundary only at shared vertices.
void Cleaner::verify() const {
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

}  // namespace cleaning

namespace {

// Cleans with the options' tolerances, then (adapt) finer ones; the first that succeeds, with a
// warning when the tolerances were finer, else the first error.
CleanPattern clean_adapting(const CreasePattern& pattern, const CleaningOptions& options) {
  try {
    return cleaning::Cleaner(pattern, options).run();
  } catch (const InputError& first) {
    if (!options.adapt) throw;
    CleaningOptions finer = options;
    for (int attempt = 0; attempt < CleaningOptions::kFinerAttempts; ++attempt) {
      finer.merge_fraction /= CleaningOptions::kFinerFactor;
      finer.snap_fraction /= CleaningOptions::kFinerFactor;
      try {
        CleanPattern out = cleaning::Cleaner(pattern, finer).run();
        out.warnings.push_back("the drawing is denser than cleaning with --merge-tol " +
                               format_number(options.merge_fraction) + " and --snap-tol " +
                               format_number(options.snap_fraction) + " allows (" + first.what() +
                               "); it was cleaned with --merge-tol " +
                               format_number(finer.merge_fraction) + " --snap-tol " +
                               format_number(finer.snap_fraction));
        return out;
      } catch (const InputError&) {
      }
    }
    throw;
  }
}

}  // namespace

CleanPattern clean_pattern(const CreasePattern& pattern, const CleaningOptions& options) {
  if (const std::string msg = options.validate(); !msg.empty()) throw UsageError(msg);
  CleaningOptions without = options;
  without.seams = false;
  try {
    return clean_adapting(pattern, without);
  } catch (const InputError&) {
    if (!options.seams) throw;
  }
  return clean_adapting(pattern, options);
}

}  // namespace sdog
