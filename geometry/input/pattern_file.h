#pragma once
// Loading a crease pattern from a file, by its type: FOLD (geometry/input/fold_reader.h) or SVG
// (geometry/input/svg_pattern.h).

#include <string>

#include "geometry/input/svg_reader.h"
#include "geometry/pattern/crease_pattern.h"

namespace sdog {

/// A file whose name ends in .fold (in any case) is read with read_fold_file (the options do not
/// apply), any other with read_svg_file + crease_pattern_from_svg.
CreasePattern read_crease_pattern(const std::string& path, const SvgReadOptions& options = {});

}  // namespace sdog
