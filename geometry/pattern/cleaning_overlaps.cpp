// Pattern cleaning, step 0: crease segments drawn along the sheet boundary, or along an earlier
// crease (a crease drawn twice), are removed before anything else; a crease loses only those
// segments and is split where they were.
#include <algorithm>
#include <unordered_map>

#include "base/text_format.h"
#include "geometry/pattern/internal/cleaner.h"
#include "geometry/pattern/plane_geometry.h"

namespace sdog::cleaning {
namespace {

// Cells of the segment index per sheet size.
constexpr int kCellsPerSide = 64;

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  return (a + param_on(p, a, b) * (b - a) - p).norm();
}

// The segments of a set of polylines, bucketed on a uniform grid for "is p near one of them".
class SegmentIndex {
 public:
  SegmentIndex(double cell, double tol) : cell_(cell), tol_(tol) {}

  void add(int owner, const Vec2& a, const Vec2& b) {
    const int id = static_cast<int>(segments_.size());
    segments_.push_back({a, b, owner});
    const Vec2 lo = a.cwiseMin(b).array() - tol_, hi = a.cwiseMax(b).array() + tol_;
    for (long i = key(lo.x()); i <= key(hi.x()); ++i)
      for (long j = key(lo.y()); j <= key(hi.y()); ++j) cells_[cell_key(i, j)].push_back(id);
  }

  /// Owners (ascending, once each) of segments within tol of p.
  std::vector<int> owners_near(const Vec2& p) const {
    std::vector<int> owners;
    const auto it = cells_.find(cell_key(key(p.x()), key(p.y())));
    if (it == cells_.end()) return owners;
    for (int id : it->second) {
      const Segment& s = segments_[id];
      if (distance_to_segment(p, s.a, s.b) <= tol_) owners.push_back(s.owner);
    }
    std::sort(owners.begin(), owners.end());
    owners.erase(std::unique(owners.begin(), owners.end()), owners.end());
    return owners;
  }

 private:
  struct Segment {
    Vec2 a, b;
    int owner;
  };
  long key(double v) const { return static_cast<long>(std::floor(v / cell_)); }
  static unsigned long long cell_key(long i, long j) {
    return (static_cast<unsigned long long>(i) << 32) ^
           (static_cast<unsigned long long>(j) & 0xffffffffULL);
  }
  double cell_, tol_;
  std::vector<Segment> segments_;
  std::unordered_map<unsigned long long, std::vector<int>> cells_;
};

// The owners near all three points a, b and their midpoint.
std::vector<int> common_owners(const SegmentIndex& index, const Vec2& a, const Vec2& b) {
  std::vector<int> owners = index.owners_near(a);
  for (const Vec2& p : {Vec2(0.5 * (a + b)), b}) {
    const std::vector<int> near = index.owners_near(p);
    std::vector<int> both;
    std::set_intersection(owners.begin(), owners.end(), near.begin(), near.end(),
                          std::back_inserter(both));
    owners = std::move(both);
  }
  return owners;
}

}  // namespace

void Cleaner::drop_overlapping_segments(double fraction) {
  const double L = std::max(sheet_.bbox.width(), sheet_.bbox.height());
  const double tol = fraction * L;
  // A segment shorter than this lies near whatever passes near it: only one drawn at the same
  // place (within kTouchFraction L, the first pass) is a redrawing.
  const double shortest = fraction > kTouchFraction ? 4 * tol : 0;
  constexpr int kBoundary = -1;
  SegmentIndex index(L / kCellsPerSide, tol);
  for (const auto& loop : loops_)
    for (size_t i = 0; i < loop.size(); ++i)
      index.add(kBoundary, loop[i], loop[(i + 1) % loop.size()]);
  std::vector<Crease> kept;
  for (int k = 0; k < static_cast<int>(creases_.size()); ++k) {
    const Crease& crease = creases_[k];
    const Polyline2& pts = crease.points;
    const int segments = segment_count(pts, crease.closed);
    std::vector<bool> drop(segments, false);
    int along_boundary = 0, along_itself = 0;
    std::vector<int> duplicated;  // earlier creases it runs along
    for (int i = 0; i < segments; ++i) {
      const Vec2 &a = pts[i], &b = pts[(i + 1) % pts.size()];
      const std::vector<int> owners = common_owners(index, a, b);
      index.add(k, a, b);  // a crease drawn back over itself runs along its own earlier segments
      if (owners.empty() || (a - b).norm() < shortest) continue;
      drop[i] = true;
      if (owners.front() == kBoundary)
        ++along_boundary;
      else if (owners.front() == k)
        ++along_itself;
      else
        duplicated.push_back(owners.front());
    }
    if (std::none_of(drop.begin(), drop.end(), [](bool d) { return d; })) {
      kept.push_back(crease);
      continue;
    }
    std::sort(duplicated.begin(), duplicated.end());
    duplicated.erase(std::unique(duplicated.begin(), duplicated.end()), duplicated.end());
    if (along_boundary > 0)
      warn(name(k) + " is drawn along the sheet boundary (" + std::to_string(along_boundary) +
           " segment(s)); that part is not a crease and is removed");
    if (along_itself > 0)
      warn(name(k) + " runs back over itself (" + std::to_string(along_itself) +
           " segment(s) drawn twice); the repeated part is removed");
    for (int j : duplicated) {
      std::string what = name(k) + " is drawn again along " + name(j) + "; merged into it";
      if (!creases_[j].folds_like(crease))
        what += " (its assignment " + std::string(enum_name(crease.fold)) + " dropped for " +
                enum_name(creases_[j].fold) + ")";
      warn(what);
    }
    // The runs of kept segments become creases (a closed crease starts after a dropped segment).
    int start = 0;
    if (crease.closed) {
      while (!drop[start]) ++start;
      start = (start + 1) % segments;
    }
    Crease part = crease;
    part.closed = false;
    part.points.clear();
    for (int n = 0; n < segments; ++n) {
      const int i = (start + n) % segments;
      if (drop[i]) {
        if (part.points.size() >= 2) kept.push_back(part);
        part.points.clear();
        continue;
      }
      if (part.points.empty()) part.points.push_back(pts[i]);
      part.points.push_back(pts[(i + 1) % pts.size()]);
    }
    if (part.points.size() >= 2) kept.push_back(part);
  }
  creases_ = std::move(kept);
}

}  // namespace sdog::cleaning
