#include "solver/modes/substep_schedule.h"

#include <algorithm>

namespace sdog {

double SubstepSchedule::next(double remaining) const {
  return std::min({1.0, 1 / remaining, size_});
}

bool SubstepSchedule::keeps(double s, double remaining, bool failed, double step_length) const {
  return !failed && (step_length >= min_step_length_ || s * remaining <= kShort || smallest(s));
}

void SubstepSchedule::kept() {
  size_ = std::min(1.0, 2 * size_);
}

void SubstepSchedule::rejected(double s) {
  size_ = std::min(size_, s) / 2;
}

}  // namespace sdog
