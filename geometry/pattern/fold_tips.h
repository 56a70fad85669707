#pragma once
// Fold tips: points inside the sheet where exactly two creases end, at an angle to each other (not
// one continuing the other), and nothing else meets; and the ends of creases inside the sheet,
// where a seam continues them (crease_pattern.h).
//
// No sheet that bends smoothly keeps a fold up to such a point. Near it the sheet is the wedge
// between the two creases and the rest, which wraps around the point. If the rest were smooth at
// the point, its tangent plane there would hold both creases and so equal the wedge's plane: both
// fold angles vanish at the tip. A fold that reaches the tip makes the rest a cone with its apex
// there, whose bending energy grows without bound towards the apex (as the logarithm of the
// distance over which it keeps the fold). Folds therefore fade towards a fold tip; on a DOG the
// fold sites within a few grid edges of it bend less than asked, or slightly the other way.
#include <array>
#include <vector>

#include "geometry/pattern/pattern_cleaning.h"

namespace sdog {

/// Two creases whose directions at a shared end differ from a straight continuation by at most
/// this (degrees) continue each other: no fold tip.
constexpr double kStraightCreaseDegrees = 5;

/// Fold sites closer than this to a fold tip (mesh units: grid edges) are counted apart when folds
/// are compared with their targets. On DOGs folded at 41x41 and 61x61 the sites that bend the other
/// way next to a fold tip lie within 5.2 grid edges of it
/// (docs/design/standard-solver.md#fold-tips).
constexpr double kFoldTipRadius = 6;

struct FoldTip {
  Eigen::Vector2d point;       ///< sheet units
  std::array<int, 2> creases;  ///< the cleaned creases that end there, ascending
  double angle_degrees = 0;  ///< between the two creases' directions away from the tip, in (0, 180]
};

/// The fold tips of a cleaned pattern (creases that are both flat make none), in junction order.
std::vector<FoldTip> fold_tips(const CleanPattern& pattern);

}  // namespace sdog
