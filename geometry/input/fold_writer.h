#pragma once
// A cleaned crease pattern as a FOLD crease pattern (https://github.com/edemaine/fold, spec 1.1):
// what the project understood of a drawing, for any FOLD viewer, and read back by
// geometry/input/fold_reader.h into the same sheet and creases.
//
// Vertices are the boundary loops' vertices and the creases' polyline vertices (shared where they
// coincide exactly: crease ends on the boundary, junctions), with FOLD's y pointing down the page
// (the sheet point (x, y) is the FOLD vertex [x, -y], as the reader expects). Edges: the boundary
// loops' edges (B), then each crease's segments in crease order (M, V, F or U), with
// edges_foldAngle the crease's signed fold angle (valleys positive) or null when the drawing gives
// none. The frame is a 2D creasePattern; file_creator names the project and file_title the source.
#include <string>

#include "geometry/pattern/pattern_cleaning.h"

namespace sdog {

/// The pattern as FOLD JSON text (indented, one line per vertex and edge).
std::string fold_text(const CleanPattern& pattern);

}  // namespace sdog
