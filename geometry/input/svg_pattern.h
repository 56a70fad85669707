#pragma once
// From an SVG drawing to a crease pattern, with the conventions of
// geometry/input/fold_conventions.h: black curves are the sheet boundary (none: the viewBox
// rectangle), the others creases.

#include "geometry/input/svg_reader.h"
#include "geometry/pattern/crease_pattern.h"

namespace sdog {

/// Sorts the drawing's curves into sheet boundary and creases. Boundary curves must form closed
/// loops (open black curves, in any order and direction, are chained end to end, each to the
/// nearest end within L/100; ends within `closed_fraction * L` become one point, a wider gap a
/// straight step); the loop of
/// largest area is the outer boundary, the others are holes and must lie inside it. Creases drawn
/// as consecutive subpaths of one <path> that continue each other are joined; a crease whose ends
/// meet within `closed_fraction * L` is closed. Throws InputError for an open or
/// self-intersecting boundary, crossing boundary loops, a hole outside the sheet, a zero-area
/// sheet, or a drawing without viewBox and without boundary.
CreasePattern crease_pattern_from_svg(const SvgDrawing& drawing, double closed_fraction = 0.002);

}  // namespace sdog
