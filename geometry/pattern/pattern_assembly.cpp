#include "geometry/pattern/pattern_assembly.h"

#include <algorithm>
#include <cmath>

#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/pattern/plane_geometry.h"

namespace sdog {
namespace {

void check_simple(const std::vector<Polyline2>& loops, const std::vector<std::string>& origins) {
  std::vector<const Polyline2*> ptrs;
  for (const auto& l : loops) ptrs.push_back(&l);
  const auto contacts = find_segment_contacts(ptrs, std::vector<bool>(loops.size(), true));
  if (contacts.empty()) return;
  const auto& c = contacts.front();
  const Polyline2& la = loops[c.a];
  const Eigen::Vector2d where = la[c.sa];
  if (c.a == c.b)
    throw InputError(origins[c.a] + ": the sheet boundary crosses itself near " +
                     format_point(where) + "; a boundary must be a simple closed curve");
  throw InputError(origins[c.b] + ": this boundary curve touches or crosses another one (" +
                   origins[c.a] + ") near " + format_point(where) +
                   "; holes must lie strictly inside the sheet and apart from each other");
}

}  // namespace

Box2 box_of(const Polyline2& points) {
  Box2 b{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const auto& p : points) {
    b.xmin = std::min(b.xmin, p.x());
    b.ymin = std::min(b.ymin, p.y());
    b.xmax = std::max(b.xmax, p.x());
    b.ymax = std::max(b.ymax, p.y());
  }
  return b;
}

Sheet sheet_from_loops(const std::vector<Polyline2>& loops,
                       const std::vector<std::string>& origins) {
  for (size_t k = 0; k < loops.size(); ++k) {
    if (loops[k].size() < 3)
      throw InputError(origins[k] +
                       ": the sheet boundary has fewer than 3 distinct points (zero area)");
  }
  check_simple(loops, origins);
  size_t outer = 0;
  for (size_t k = 1; k < loops.size(); ++k)
    if (std::abs(signed_area(loops[k])) > std::abs(signed_area(loops[outer]))) outer = k;
  const Box2 b = box_of(loops[outer]);
  const double area = std::abs(signed_area(loops[outer]));
  const double L = std::max(b.width(), b.height());
  if (!(area > 1e-12 * L * L) || !(L > 0))
    throw InputError(origins[outer] + ": the sheet has zero area (its boundary encloses " +
                     format_number(area) + " square units)");
  Sheet sheet;
  sheet.outer = loops[outer];
  if (signed_area(sheet.outer) < 0) std::reverse(sheet.outer.begin(), sheet.outer.end());
  for (size_t k = 0; k < loops.size(); ++k) {
    if (k == outer) continue;
    if (point_in_polygon(loops[k].front(), sheet.outer) != 1)
      throw InputError(origins[k] + ": this boundary loop lies outside the sheet (" +
                       origins[outer] + "); holes must lie inside the outer boundary");
    Polyline2 hole = loops[k];
    if (signed_area(hole) > 0) std::reverse(hole.begin(), hole.end());
    sheet.holes.push_back(std::move(hole));
  }
  return sheet;
}

void check_near_sheet(const Polyline2& points, const std::string& origin,
                      const CreasePattern& pattern) {
  constexpr double kFarFactor = 100;
  const Box2& b = pattern.sheet.bbox;
  const double L = pattern.size();
  for (const auto& p : points) {
    if (p.x() < b.xmin - kFarFactor * L || p.x() > b.xmax + kFarFactor * L ||
        p.y() < b.ymin - kFarFactor * L || p.y() > b.ymax + kFarFactor * L)
      throw InputError(origin + ": the curve reaches " + format_point(p) + ", more than " +
                       format_number(kFarFactor) +
                       " sheet sizes away from the sheet; check the drawing's coordinates");
  }
}

}  // namespace sdog
