#pragma once
// The exact part of meshing (CGAL, exact kernel): creases and boundary snapped to the grid, the
// planar arrangement of those snapped curves, its faces (the patches), which grid cells each
// patch owns, and the crease points with the patches they touch.
//
// Snapping: every curve is replaced by its crossings with the grid lines, in order along the
// curve, so that inside a cell a curve is one straight chord between two points on the cell's
// edges. A cell belongs to a patch iff area(cell ∩ patch) > 0, decided exactly: cells no chord
// cuts are flood-filled between blocking edges and located once per component; cut cells are
// split by their chords into convex pieces, and each piece is located by an interior point.
//
// Patch order (deterministic, documented): cells are numbered row by row from the bottom-left
// (cell (i, j) has number j * (x_res - 1) + i); patches are sorted by the ascending list of the
// numbers of their cells, compared lexicographically: first by their first cell, patches sharing
// it by their second cell, and so on. The order depends only on which cells a patch owns, not on
// the exact position of a crease inside a cell.
#include <Eigen/Core>
#include <vector>

#include "geometry/mesh/grid.h"
#include "geometry/pattern/pattern_cleaning.h"

namespace sdog {

/// A point on a grid edge: p = t * v(i0, j0) + (1 - t) * v(i1, j1), where (i0, j0) is the end
/// with the smaller coordinate. On a grid vertex both ends are that vertex and t = 1.
struct GridEdgePoint {
  int i0 = 0, j0 = 0, i1 = 0, j1 = 0;
  double t = 1;
  bool on_vertex() const { return i0 == i1 && j0 == j1; }
};

struct PatchLayout {
  std::vector<double> xs, ys;  ///< grid line coordinates in sheet units
  int patch_count = 0;
  /// Owners of cell (i, j), cell index j * (nx - 1) + i: patches cell_patches[cell_offsets[c] ..
  /// cell_offsets[c + 1]), ascending.
  std::vector<int> cell_offsets, cell_patches;

  struct CreasePoint {
    Eigen::Vector2d position;  ///< sheet units
    GridEdgePoint edge;
    std::vector<int> patches;  ///< patches whose closure contains the point, ascending
  };
  std::vector<CreasePoint> points;  ///< unique: a junction is one point shared by its creases

  struct Curve {
    std::vector<int> points;  ///< indices into `points`, in order along the crease
    bool closed = false;      ///< the last point connects to the first (not repeated)
    bool slit = false;        ///< a slit: its two sides are free (CurveKind::kSlit)
  };
  std::vector<Curve> curves;  ///< one per cleaned crease, same order

  std::vector<Polyline2> boundary;  ///< the snapped boundary loops, for drawing

  /// The part of a cut cell (one that a snapped crease or the boundary crosses) that lies in one
  /// patch: a convex polygon, counter-clockwise, in cell coordinates: (u, v) in [0, 1]^2 from the
  /// cell's lower-left corner along x and y. Every vertex lies on the cell's boundary (the chords
  /// of a cell end on its edges). Pieces outside the sheet (in a hole, beyond the boundary) are
  /// not listed. A piece without points marks a cell that a patch owns without any of its area (a
  /// coarse cell added to cover a fine patch, fine_coarse_map.h).
  struct CellPiece {
    int cell = 0, patch = 0;
    std::vector<Eigen::Vector2d> uv;
  };
  std::vector<CellPiece> pieces;  ///< of every cut cell, by cell, then from bottom to top

  int nx() const { return static_cast<int>(xs.size()); }
  int ny() const { return static_cast<int>(ys.size()); }
  int cell_count() const { return (nx() - 1) * (ny() - 1); }
  int owner_count(int cell) const { return cell_offsets[cell + 1] - cell_offsets[cell]; }
  const int* owners(int cell) const { return cell_patches.data() + cell_offsets[cell]; }
};

/// Snaps the cleaned pattern to the grid given by the two axis layouts and finds its patches.
/// `closed_start_stride` = 2 starts closed creases at their first crossing with an even line
/// (nested fine grid), so that fine and coarse curves start at the same point; 1 otherwise.
/// Throws UsageError when a closed crease or a hole falls inside a single cell.
PatchLayout build_patch_layout(const CleanPattern& pattern, const AxisLayout& x,
                               const AxisLayout& y, int closed_start_stride = 1);

/// Renumbers the patches: new id of patch p is new_id[p].
void renumber_patches(PatchLayout& layout, const std::vector<int>& new_id);

}  // namespace sdog
