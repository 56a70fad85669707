#pragma once
// The DOG quad mesh of one resolution: grid cells owned by patches, each patch one contiguous
// vertex range, in its flat rest state; plus the crease stitching that ties the patches together.
//
// Units: mesh = (sheet - sheet_origin) * scale with scale = (x_res_fine - 1) / sheet width, so a
// uniform fine grid column has width 1 (the thesis's convention: a fine grid edge has length 1).
// The coarse mesh uses the same units (its uniform edges have length 2), so a link vertex and its
// fine twin have identical coordinates.
#include <Eigen/Core>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/patch_layout.h"

namespace sdog {

/// A point on a mesh edge: p = t * V[v1] + (1 - t) * V[v2]. On a vertex v1 == v2 and t = 1.
struct EdgePoint {
  int v1 = -1, v2 = -1;
  double t = 1;
  bool operator==(const EdgePoint& o) const { return v1 == o.v1 && v2 == o.v2 && t == o.t; }
};

struct CreaseStitching {
  struct Point {
    Eigen::Vector2d flat;           ///< position in the flat mesh (mesh units)
    std::vector<EdgePoint> copies;  ///< one per patch that owns the edge, in patch order
    std::vector<int> patches;       ///< the patch of each copy
  };
  std::vector<Point> points;  ///< unique crease points (a junction is one point)

  /// Stitching pair: copies `a` and `b` of point `point` must coincide. With m copies there are
  /// m - 1 chained pairs (0,1), (1,2), ...; a point that lies on slits only has none (the slit's
  /// two sides are free).
  struct Pair {
    int point, a, b;
  };
  std::vector<Pair> pairs;

  struct Curve {
    std::vector<int> points;  ///< crease points in order along the crease
    bool closed = false;
    Fold fold =
        Fold::kUnassigned;  ///< the cleaned crease's assignment and angle (crease_pattern.h)
    std::optional<double> angle;
    std::string id;  ///< its element id
    CurveKind kind = CurveKind::kCrease;
  };
  std::vector<Curve> curves;  ///< one per cleaned crease
  /// Whether some curve is of kind `kind` (a slit, a seam).
  bool has(CurveKind kind) const {
    for (const Curve& c : curves)
      if (c.kind == kind) return true;
    return false;
  }

  std::vector<std::vector<int>> patch_adjacency;  ///< patches sharing a crease, ascending
  std::vector<int> junctions;  ///< crease points with copies in more than two patches
};

struct DogMesh {
  Eigen::MatrixX3d V;  ///< flat rest positions (z = 0)
  Eigen::MatrixX4i F;  ///< quads (i,j) (i+1,j) (i+1,j+1) (i,j+1): counter-clockwise seen from +z
  std::vector<int> patch_begin;       ///< patch p owns vertices [patch_begin[p], patch_begin[p+1])
  std::vector<int> quad_patch_begin;  ///< and quads [quad_patch_begin[p], quad_patch_begin[p+1])
  std::vector<int> vertex_patch;      ///< patch of each vertex
  std::vector<Eigen::Vector2i> grid;  ///< grid line indices (i, j) of each vertex
  std::vector<double> xs, ys;         ///< grid line coordinates in mesh units
  Eigen::Vector2d sheet_origin = Eigen::Vector2d::Zero();
  double scale = 1;
  CreaseStitching stitching;
  /// Where folds fade: the pattern's fold tips (geometry/pattern/fold_tips.h), mesh units.
  std::vector<Eigen::Vector2d> fold_tips;
  /// The quads whose cell a crease or the boundary cuts, with the part of the cell that belongs to
  /// their patch: a convex polygon, counter-clockwise, in the quad's cell coordinates (u, v) in
  /// [0, 1]^2 from F(q, 0) towards F(q, 1) and F(q, 3) (PatchLayout::CellPiece). A quad may have
  /// several pieces, or one without points (none of its cell lies in the patch); quads not listed
  /// lie wholly in their patch. Sorted by quad.
  struct QuadPiece {
    int quad = 0;
    std::vector<Eigen::Vector2d> uv;
  };
  std::vector<QuadPiece> quad_pieces;

  int vertex_count() const { return static_cast<int>(V.rows()); }
  int quad_count() const { return static_cast<int>(F.rows()); }
  int patch_count() const { return static_cast<int>(patch_begin.size()) - 1; }
  int nx() const { return static_cast<int>(xs.size()); }
  int ny() const { return static_cast<int>(ys.size()); }
  /// Vertex of patch p at grid position (i, j), or -1 (binary search in the patch's range).
  int vertex_at(int patch, int i, int j) const;
  /// Mesh coordinates of a point given in sheet units.
  Eigen::Vector2d to_mesh(const Eigen::Vector2d& sheet) const {
    return (sheet - sheet_origin) * scale;
  }
  /// Position of an edge point in the current positions X (n x 3).
  static Eigen::Vector3d position(const Eigen::MatrixX3d& X, const EdgePoint& e) {
    return e.t * X.row(e.v1).transpose() + (1 - e.t) * X.row(e.v2).transpose();
  }
};

/// The quads of a mesh by patch and the grid position of their lower-left vertex F(q, 0).
using QuadCorner = std::array<int, 3>;  // patch, grid i, grid j
std::map<QuadCorner, int> quads_by_corner(const DogMesh& mesh);

/// Crease points closer than this (mesh units) to a grid vertex are taken onto it in pairs (below).
constexpr double kVertexCreaseDistance = 0.02;

/// Builds the mesh and its stitching from a patch layout (see the unit convention above).
///
/// A crease that passes within kVertexCreaseDistance of a grid vertex crosses the two grid lines
/// through it at two nearly coincident crease points. Their stitching rows are nearly parallel,
/// and once the sheet is folded and curved the two patches' edge chords cannot meet at both:
/// restoration stalls with the two gaps equal and opposite (around 1e-3 mesh units). The
/// stitching takes such a pair (consecutive along one crease, between the same two patches) as one
/// crease point on the vertex, which moves the crease by at most kVertexCreaseDistance; cells and
/// vertices stay as the layout made them. `coarse_step` 2 marks the fine mesh of nested grids
/// (coarse line k is line 2k): there a pair is taken onto a vertex only where the coarse mesh does
/// the same (a coarse vertex) or has neither point (both lines fine-only), so that coarse crease
/// points stay fine ones. A run of consecutive crease points on one grid edge, between the same two
/// patches and within kVertexCreaseDistance of the first (a crease that touches a grid line), has
/// nearly equal stitching rows that stall restoration in the same way; it is taken as its middle
/// point.
/// Throws std::logic_error if a crease point ends up with fewer than two copies.
DogMesh build_dog_mesh(const PatchLayout& layout, const Eigen::Vector2d& sheet_origin, double scale,
                       int coarse_step = 1);

}  // namespace sdog
