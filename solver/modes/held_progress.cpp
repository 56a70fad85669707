#include "solver/modes/held_progress.h"

#include <algorithm>
#include <cmath>

namespace sdog {

bool HeldProgress::lowers(double f) {
  const double margin = decrease_ * std::max(std::abs(f), 1.0);
  if (!best_ || f < *best_ - margin) {
    best_ = f;
    without_progress_ = 0;
    return true;
  }
  best_ = std::min(*best_, f);
  return ++without_progress_ < kHeldWithoutProgress;
}

}  // namespace sdog
