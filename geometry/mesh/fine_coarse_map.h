#pragma once
// The map between the fine DOG and its coarse twin (coarse line j = fine line 2j, same units).
// Inside each patch, by the parity of a fine vertex's grid position (i, j):
//   link (even, even): the same vertex as coarse (i/2, j/2);
//   I    (one odd):    the midpoint of a coarse edge;
//   X    (odd, odd):   the centre of a coarse quad;
// and coarse-only: coarse vertices without a fine twin (beyond a crease from the rest of their
// patch). Crease curves correspond point by point where both meshes have a crease point; the fine
// points between two coarse ones store their arc-length fraction along the flat fine curve.
#include <array>
#include <vector>

#include "base/enum_names.h"
#include "geometry/mesh/dog_mesh.h"
#include "geometry/mesh/patch_layout.h"

namespace sdog {

enum class VertexType : int { kLink = 0, kI = 1, kX = 2, kCoarseOnly = 3 };
template <>
struct EnumNames<VertexType> {
  static constexpr const char* noun = "vertex type";
  static constexpr EnumName<VertexType> rows[] = {
      {VertexType::kLink, "link"},
      {VertexType::kI, "I"},
      {VertexType::kX, "X"},
      {VertexType::kCoarseOnly, "coarse-only"},
  };
};

struct FineCoarseMap {
  std::vector<VertexType> fine_type;                    ///< Link, I or X
  std::vector<VertexType> coarse_type;                  ///< Link or CoarseOnly
  std::vector<int> fine_to_coarse;                      ///< coarse twin of a link vertex, else -1
  std::vector<int> coarse_to_fine;                      ///< fine twin of a link vertex, else -1
  std::vector<std::array<int, 2>> fine_to_coarse_edge;  ///< I vertex: ends of its coarse edge
  std::vector<int> fine_to_coarse_quad;  ///< X vertex: the coarse quad it is the centre of

  /// For fine crease point k of curve c: if the coarse curve has the same point, `coarse` is its
  /// index along the coarse curve (where the two meshes took a crease that touches a grid line
  /// or passes a grid vertex as different points, the fine point within 2 kVertexCreaseDistance
  /// of the coarse one stands for it); otherwise the point lies between coarse points `segment` and
  /// `segment + 1` (cyclically for closed curves) at arc-length fraction `fraction` in (0, 1).
  /// Segment -1: no coarse point lies on one side of it along an open crease (the alternative
  /// coarse DOG, alt_coarse.h, keeps no crease end), so nothing interpolates it.
  struct CurvePoint {
    int coarse = -1;
    int segment = -1;
    double fraction = 0;
  };
  std::vector<std::vector<CurvePoint>> curves;

  int link_count = 0, i_count = 0, x_count = 0, coarse_only_count = 0;
  /// Fine vertices without their coarse vertex, edge or quad (the alternative coarse DOG only).
  int uncovered_count = 0;
};

/// A map of the given sizes with nothing mapped: every fine vertex X without a coarse quad, every
/// coarse vertex of `coarse_type` without a fine twin.
FineCoarseMap unmapped(int fine_vertices, int coarse_vertices, VertexType coarse_type);

/// Sets the link, I, X and coarse-only counts from the vertex types.
void count_vertex_types(FineCoarseMap& map);

/// How the coarse curves cover the fine crease points, counted along every crease (a junction once
/// per crease through it): kept as coarse points, interpolated between two, or neither.
struct CurveCoverage {
  int kept = 0, interpolated = 0, uninterpolable = 0;
};
CurveCoverage curve_coverage(const FineCoarseMap& map);

/// The map of fine crease curve `curve` given the indices along it of the points that the coarse
/// curve keeps, in order: those get their coarse index, the points between two kept ones their
/// arc-length fraction (cyclically for a closed curve), the others of an open curve segment -1.
std::vector<FineCoarseMap::CurvePoint> interpolated_curve(const CreaseStitching& fine,
                                                          const CreaseStitching::Curve& curve,
                                                          const std::vector<int>& coarse_at);

/// Coarse patch ids that match the fine ones: result[c] is the fine patch that coarse patch c
/// covers (most shared cells). Throws UsageError when this is not one to one.
std::vector<int> match_coarse_patches(const PatchLayout& fine, const PatchLayout& coarse);

/// Makes every coarse patch cover its fine patch: a coarse cell also belongs to each patch that
/// owns one of its four fine cells. (Where a crease dips across a coarse grid line and back within
/// one coarse cell, the coarse chord runs along the line and the coarse patch would miss cells that
/// the fine patch has.) Patch ids must already match. Returns the number of (cell, patch) pairs
/// added.
int cover_fine_patches(PatchLayout& coarse, const PatchLayout& fine);

/// Builds the map. The meshes must come from nested grids with matched patch ids and coarse
/// patches that cover the fine ones (cover_fine_patches).
FineCoarseMap build_fine_coarse_map(const DogMesh& fine, const DogMesh& coarse);

}  // namespace sdog
