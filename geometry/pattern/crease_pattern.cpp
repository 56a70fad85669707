#include "geometry/pattern/crease_pattern.h"

namespace sdog {

double fold_sign(Fold fold) {
  return fold == Fold::kValley ? 1.0 : fold == Fold::kMountain ? -1.0 : 0.0;
}

}  // namespace sdog
