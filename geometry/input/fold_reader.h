#pragma once
// FOLD crease-pattern reader. FOLD is the origami community's JSON format for crease patterns and
// folded states (github.com/edemaine/fold, doc/spec.md); this reader takes crease patterns.
//
// What is read, from the top-level frame (FOLD's key frame; the frames listed in file_frames are
// not read); every other key is ignored:
//  - vertices_coords: [x, y] for each vertex. Longer arrays are accepted when every coordinate
//    after y is 0 ([x, y, 0]): a crease pattern is flat.
//  - edges_vertices: [u, v] for each edge, two different vertex indices counted from 0.
//  - edges_assignment: one letter for each edge, upper or lower case: B the sheet boundary, M a
//    mountain crease, V a valley crease, F a flat crease, U a crease without assignment, J a join
//    edge (a modelling helper, not a crease, as the seams this project writes: ignored, with a
//    warning), C a cut: a slit (crease_pattern.h) whose two sides are free.
//  - edges_foldAngle (optional): the fold angle of each edge in degrees, -180 to 180, or null for
//    none. FOLD's sign is this project's (geometry/input/fold_conventions.h): valleys positive,
//    mountains negative. Crease::angle is its magnitude; a sign that contradicts M or V, or a
//    nonzero angle on a B or F edge, is an error. A U edge with a nonzero angle becomes a mountain
//    or a valley by the sign; 0 on a U edge means no angle.
//  - frame_classes (optional): a frame that is a "foldedForm" and not a "creasePattern" is
//    refused (its coordinates are a folded state, not the flat sheet).
//
// Coordinates: the FOLD point (x, y) becomes (x, -y) in sheet units, as the SVG reader negates
// SVG's y axis, so that a FOLD crease pattern appears the same way round as the SVG it was made
// from. FOLD does not fix the direction of y. Origami Simulator turns the SVG point (x, y) into
// the FOLD vertex [x, y] when it converts an SVG pattern, and places and draws the vertex [x, y] of
// a FOLD crease pattern where it would the SVG point (x, y): FOLD's y, like SVG's, points down the
// page. (Its FOLD export is the folded model, 3D vertices marked "foldedForm", and is refused.)
//
// The sheet: the B edges, chained into closed loops (every vertex of a loop has exactly two B
// edges). The loop of largest area is the outer boundary (counter-clockwise), the others are holes
// (clockwise), as for the SVG reader's black loops. Each loop is named "FILE: edge N" after its
// lowest-numbered edge.
//
// The creases: the M, V, F and U edges. Edges of the same assignment and fold angle that continue
// each other in a straight line (at a vertex where exactly two edges of that assignment and angle
// meet, collinear within a relative 1e-9) form one crease, a polyline through all their vertices;
// every other edge is a crease of its own (pattern cleaning joins creases that meet alone at an
// interior vertex, such as the pieces of a curved crease). Creases are ordered by their
// lowest-numbered edge N; Crease::id is "edge N" and Crease::origin "FILE: edge N".
//
// Errors are InputError, one line naming the file, and the key and index or the edge:
// "p.fold: $.edges_vertices[4][1]: vertex 12 does not exist (vertices_coords has 10 vertices,
// numbered from 0)". Refused: text that is not JSON (with nlohmann's line and column), a missing
// or wrongly typed key (edges_assignment too: without it the boundary is unknown), arrays whose
// lengths differ from edges_vertices, a vertex index out of range, an edge from a vertex to
// itself or of zero length, a coordinate that is not a finite number or a nonzero z, an unknown
// assignment letter, a fold angle outside [-180, 180] or contradicting the assignment,
// no B edge, a boundary that stops at a vertex with one B edge or branches at a vertex with more
// than two, boundary loops that cross, a hole outside the sheet, and a sheet of zero area. An edge
// that joins the same two vertices as an earlier one is dropped with a warning (pattern.warnings).
#include <string>

#include "geometry/pattern/crease_pattern.h"

namespace sdog {

/// Reads the FOLD file at `path` (see above). Throws InputError "PATH: cannot open file (...)"
/// when it cannot be read.
CreasePattern read_fold_file(const std::string& path);

/// Same as read_fold_file, from text already in memory; `source` names it in messages.
CreasePattern parse_fold(const std::string& text, const std::string& source);

}  // namespace sdog
