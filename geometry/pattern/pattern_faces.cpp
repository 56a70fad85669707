#include "geometry/pattern/pattern_faces.h"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <set>
#include <utility>

namespace sdog {
namespace {

using K = CGAL::Epeck;
using Traits = CGAL::Arr_segment_traits_2<K>;
using Arrangement = CGAL::Arrangement_2<Traits>;

// The arrangement of the cleaned pattern's boundary and creases.
Arrangement pattern_arrangement(const CleanPattern& pattern) {
  std::vector<Traits::Curve_2> segs;
  auto add = [&](const Polyline2& pts, bool closed) {
    for (int k = 0; k < segment_count(pts, closed); ++k) {
      const Eigen::Vector2d& a = pts[k];
      const Eigen::Vector2d& b = pts[(k + 1) % pts.size()];
      if (a != b) segs.emplace_back(K::Point_2(a.x(), a.y()), K::Point_2(b.x(), b.y()));
    }
  };
  add(pattern.sheet.outer, true);
  for (const auto& h : pattern.sheet.holes) add(h, true);
  for (const auto& c : pattern.creases) add(c.points, c.closed);
  Arrangement arr;
  CGAL::insert(arr, segs.begin(), segs.end());
  return arr;
}

std::pair<double, double> coordinates(const K::Point_2& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
}

}  // namespace

int count_pattern_patches(const CleanPattern& pattern) {
  const Arrangement arr = pattern_arrangement(pattern);
  // Bounded faces minus the holes (cleaning removed every crease inside a hole).
  return static_cast<int>(arr.number_of_faces()) - 1 - static_cast<int>(pattern.sheet.holes.size());
}

int first_non_separating_crease(const CleanPattern& pattern) {
  const Arrangement arr = pattern_arrangement(pattern);
  // After cleaning, creases meet only at shared vertices, so each crease segment is one edge of
  // the arrangement: a crease divides the sheet where the faces on the two sides of an edge differ.
  // Edges with the same face on both sides (their ends as the input doubles, in both orders):
  std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> inside;
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    if (e->face() != e->twin()->face()) continue;
    const auto s = coordinates(e->source()->point()), t = coordinates(e->target()->point());
    inside.insert({s, t});
    inside.insert({t, s});
  }
  for (size_t k = 0; k < pattern.creases.size(); ++k) {
    const Crease& c = pattern.creases[k];
    for (int i = 0; i < segment_count(c.points, c.closed); ++i) {
      const Eigen::Vector2d& a = c.points[i];
      const Eigen::Vector2d& b = c.points[(i + 1) % c.points.size()];
      if (inside.count({{a.x(), a.y()}, {b.x(), b.y()}})) return static_cast<int>(k);
    }
  }
  return -1;
}

}  // namespace sdog
