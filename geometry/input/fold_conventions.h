#pragma once
// How a drawn curve is read: as the sheet boundary, a crease (with its fold assignment and angle),
// a cut line or a facet line. The first rule that applies decides:
//
//  1. This project's attributes, on the element or an enclosing group: data-fold="mountain",
//     "valley", "flat" or "unassigned", and data-angle="DEG", the fold angle in degrees (0 to
//     180; its direction is the assignment's). An element with either is a crease, whatever its
//     colour; data-angle alone keeps the assignment of the rules below.
//  2. Layers: the nearest enclosing group whose name (Inkscape's layer label, else its id) holds
//     exactly one of the words mountain, valley, cut, boundary or outline, in any case and as part
//     of a longer name ("MountainLine", "Valley_Fold", "cut lines"), makes its curves mountains,
//     valleys, cut lines or sheet boundary. A name with two of the words says nothing.
//  3. Origami Simulator's colours (exact values): black #000000 the sheet boundary, red #ff0000
//     mountain, blue #0000ff valley, magenta #ff00ff a crease without assignment, green #00ff00
//     (or CSS "green", #008000) a cut, yellow #ffff00 a facet line (a triangulation helper, not a
//     crease: ignored). The opacity of a red or blue line, when the drawing sets one (opacity
//     times stroke-opacity), is its fold angle as a share of 180 degrees (also when a layer
//     gives the line the same assignment).
//  4. Origami diagrams' dashes: a dash-dot line (dashes of different lengths) is a mountain, a
//     dashed line a valley; a dashed or dash-dot black line is a crease, not the boundary.
//  5. Any other colour: a crease without assignment.
//
// Cut lines cut the paper: they outline the sheet or cut holes out of it, and are joined with the
// black boundary curves into the sheet's boundary loops. An open cut or black line that ends
// inside the sheet (one end that meets no other boundary or cut line) is a slit
// (crease_pattern.h): the paper is cut along it and its two sides are free.
//
// Sign convention (FOLD's edges_foldAngle): valley folds have positive angles, mountain folds
// negative ones. Seen from +z (the drawing as drawn, y up), a valley fold lifts both sides of the
// crease towards the viewer.
#include <optional>
#include <string>

#include "geometry/input/svg_reader.h"
#include "geometry/pattern/crease_pattern.h"

namespace sdog {

enum class CurveRole { kBoundary, kCrease, kCut, kFacet };

struct CurveReading {
  CurveRole role = CurveRole::kCrease;
  Fold fold = Fold::kUnassigned;
  std::optional<double> angle;  ///< degrees, 0 to 180, when the drawing gives one
  std::string layer;            ///< the group name that gave the meaning (rule 2), or empty
};

/// The meaning a group name gives its curves (rule 2), unset when it names none or several.
std::optional<CurveReading> layer_meaning(const std::string& group_name);

/// Reads one curve with the rules above. Throws InputError naming `where` (the element) for a
/// data-fold or data-angle value it cannot read.
CurveReading read_curve(const SvgCurve& curve, const std::string& where);

}  // namespace sdog
