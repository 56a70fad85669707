#pragma once
// The model the studio shows: a crease pattern meshed at a resolution. Odd resolutions (both
// values) also get the coarse mesh and the fine/coarse map; even ones the fine mesh only, so that
// the coarse modes then refuse to run with a message.
#include <memory>
#include <string>

#include "geometry/mesh/dog_model.h"

namespace sdog::studio {

/// Reads the pattern (SVG or FOLD) and builds the model; `resolution` is "XxY" or "auto" (41 grid
/// lines along the sheet's longer side, as sdog's default). Throws the geometry library's errors
/// (UsageError for a resolution that cannot work, InputError for a pattern that cannot be read or
/// meshed).
std::shared_ptr<const DogModel> load_model(const std::string& pattern_path,
                                           const std::string& resolution);

}  // namespace sdog::studio
