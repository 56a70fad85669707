#pragma once
// Colours shared by every picture (the thesis's conventions for the fine/coarse map).
#include <array>

#include "geometry/mesh/fine_coarse_map.h"
#include "geometry/pattern/crease_pattern.h"

namespace sdog::vis {

using Rgb = std::array<double, 3>;

inline Rgb vertex_type_colour(VertexType t) {
  switch (t) {
    case VertexType::kLink:
      return {0.17, 0.63, 0.17};  // green
    case VertexType::kI:
      return {0.45, 0.78, 0.98};  // light blue
    case VertexType::kX:
      return {0.52, 0.29, 0.72};  // purple
    case VertexType::kCoarseOnly:
      return {0.86, 0.12, 0.12};  // red
  }
  return {0, 0, 0};
}
/// Vertices of a mesh without a fine/coarse map (no types).
inline constexpr Rgb kUntypedVertexColour{0.4, 0.4, 0.4};
inline constexpr Rgb kCreasePointColour{1.0, 0.45, 0.75};  // pink
/// Crease lines by assignment (crease_pattern.h): mountain red, valley blue, unassigned grey,
/// flat light grey (a crease that stays flat hardly matters to the shape).
inline Rgb fold_colour(Fold fold) {
  switch (fold) {
    case Fold::kMountain:
      return {0.85, 0.10, 0.10};
    case Fold::kValley:
      return {0.10, 0.35, 0.85};
    case Fold::kFlat:
      return {0.80, 0.80, 0.80};
    case Fold::kUnassigned:
      break;
  }
  return {0.40, 0.40, 0.40};
}
/// Slits (crease_pattern.h) in the crease lines: green, as cut lines are drawn.
inline constexpr Rgb kSlitColour{0.10, 0.60, 0.20};
inline constexpr Rgb kSurfaceColour{0.94, 0.94, 0.94};
inline constexpr Rgb kPaperColour{0.97, 0.96, 0.92};      // the paper style's front side
inline constexpr Rgb kPaperBackColour{0.78, 0.82, 0.88};  // and its back side
inline constexpr Rgb kEdgeColour{0.62, 0.62, 0.62};
inline constexpr Rgb kTextColour{0.1, 0.1, 0.1};
inline constexpr Rgb kLinkLineColour{0.15, 0.15, 0.15};
inline constexpr Rgb kHandleColour{0.95, 0.55, 0.05};     // orange
inline constexpr Rgb kSelectionColour{0.05, 0.05, 0.05};  // the studio's selected vertices: black
inline constexpr Rgb kTargetColour{0.10, 0.20, 0.60};     // dark blue
inline constexpr Rgb kResidualLineColour{0.85, 0.10, 0.10};  // red
inline constexpr Rgb kAngleSiteColour{0.00, 0.75, 0.80};     // cyan
inline constexpr Rgb kCoarseEdgeColour{0.20, 0.30, 0.75};    // the coarse mesh over the fine one

/// The number of patch colours: light, distinct colours (the vertex and handle colours stay
/// readable on them); patches beyond it take them again from the start.
inline constexpr int kPatchColours = 12;
inline Rgb patch_colour(int index) {
  static constexpr Rgb colours[kPatchColours] = {
      {0.99, 0.80, 0.60}, {0.70, 0.85, 0.95}, {0.78, 0.92, 0.70}, {0.95, 0.75, 0.85},
      {0.85, 0.80, 0.95}, {0.98, 0.93, 0.62}, {0.72, 0.90, 0.88}, {0.90, 0.82, 0.72},
      {0.96, 0.66, 0.62}, {0.86, 0.95, 0.56}, {0.66, 0.74, 0.92}, {0.88, 0.68, 0.92}};
  return colours[((index % kPatchColours) + kPatchColours) % kPatchColours];
}

/// Colours of the lines of a chart, told apart also by colour-blind readers (the Okabe-Ito
/// palette without its yellow, which is too faint on white): blue, vermillion, bluish green,
/// reddish purple, orange, sky blue, black; then again from the start.
inline Rgb series_colour(int index) {
  static constexpr Rgb colours[] = {{0.00, 0.45, 0.70}, {0.84, 0.37, 0.00}, {0.00, 0.62, 0.45},
                                    {0.80, 0.47, 0.65}, {0.90, 0.62, 0.00}, {0.34, 0.71, 0.91},
                                    {0.00, 0.00, 0.00}};
  constexpr int n = sizeof colours / sizeof colours[0];
  return colours[((index % n) + n) % n];
}

}  // namespace sdog::vis
