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
  struct CurvePoint {
    int coarse = -1;
    int segment = -1;
    double fraction = 0;
  };
  std::vector<std::vector<CurvePoint>> curves;

  int link_count = 0, i_count = 0, x_count = 0, coarse_only_count = 0;
};

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
