#pragma once
// The steps of building a CreasePattern that the SVG and FOLD readers share: the sheet from its
// boundary loops, and the check that creases stay near the sheet.
#include <string>
#include <vector>

#include "geometry/pattern/crease_pattern.h"

namespace sdog {

/// The bounding box of the points.
Box2 box_of(const Polyline2& points);

/// The sheet of closed boundary loops (first point not repeated); `origins[k]` names loop k in
/// messages. The loop of largest area is the outer boundary (made counter-clockwise), the others
/// are holes inside it (made clockwise); bbox is not set. Throws InputError for a loop with fewer
/// than 3 points, a loop that crosses itself, loops that touch or cross each other, a hole outside
/// the outer boundary, and a sheet of zero area.
Sheet sheet_from_loops(const std::vector<Polyline2>& loops,
                       const std::vector<std::string>& origins);

/// Creases may reach past the sheet (they are clipped), but coordinates many sheet sizes away are
/// a drawing mistake, and they would make clipping and crossing searches needlessly expensive.
/// Throws InputError naming `origin` when a point lies more than 100 sheet sizes outside the
/// sheet's bounding box (pattern.sheet.bbox must be set).
void check_near_sheet(const Polyline2& points, const std::string& origin,
                      const CreasePattern& pattern);

}  // namespace sdog
