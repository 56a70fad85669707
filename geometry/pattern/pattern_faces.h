#pragma once
// The faces of a cleaned crease pattern: the pieces its creases and boundary cut the sheet into,
// from the exact arrangement of its segments.

#include "geometry/pattern/pattern_cleaning.h"

namespace sdog {

/// Number of patches of the cleaned pattern itself (faces of the arrangement of its creases and
/// boundary inside the sheet): what every grid resolution must reproduce.
int count_pattern_patches(const CleanPattern& pattern);

/// The first crease of the cleaned pattern whose two sides lie in the same patch (it ends inside
/// the sheet's piece on both sides, as a crease from the outer boundary to a hole), or -1.
int first_non_separating_crease(const CleanPattern& pattern);

}  // namespace sdog
