#pragma once
// A trimmed surface (trimmed_surface.h) as a FOLD folded form (github.com/edemaine/fold, spec 1.2),
// for Origami Simulator and the FOLD tools: frame_classes ["foldedForm"], 3D vertices_coords,
// faces_vertices (the surface's triangles) and every triangle edge once, with its assignment and
// the fold angle the state reaches there.
//
// The surface's patches share no vertex; vertices of different patches closer than the weld
// tolerance are one FOLD vertex, so that stitched creases and seams join their two sides. The
// caller's tolerance, kWeldGridEdges grid edges, also joins the two sides of a crease point the
// stitching took onto a grid vertex (dog_mesh.h: kVertexCreaseDistance), and the two sides of a
// slit where they lie that close (a slit that has not opened there). An edge with one triangle is
// B (boundary); an edge between two patches is a crease, M or V by the sign of the angle reached
// there, F where it is within kFlatDegrees of flat (a seam, an unfolded crease); an edge inside a
// patch is J (a triangulation edge: its two faces are one). edges_foldAngle is the signed angle
// between the two triangles' normals in degrees (FOLD's sign: positive where the faces turn towards
// their normals, a valley; the normals are those of the drawing's side, +z at rest), 0 on B edges.
#include <string>

#include "geometry/surface/trimmed_surface.h"

namespace sdog {

constexpr double kWeldGridEdges = 0.05;
constexpr double kFlatDegrees = 0.5;

/// The FOLD text of `surface`, whose positions are in the units to write (sheet units), vertices
/// of different patches within `weld_tolerance` (those units) welded; `title` names the state
/// ("frame_title").
std::string folded_form_fold(const TrimmedSurface& surface, double weld_tolerance,
                             const std::string& title);

}  // namespace sdog
