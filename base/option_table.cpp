#include "base/option_table.h"

#include <cmath>

#include "base/text_format.h"

namespace sdog {

bool Bounds::contains(double v) const {
  if (std::isnan(v) || std::isinf(v)) return false;
  const bool low = open_min ? v > min : v >= min;
  const bool high = open_max ? v < max : v <= max;
  return low && high;
}

std::string Bounds::symbols() const {
  const bool low = std::isfinite(min), high = std::isfinite(max);
  if (low && high)
    return std::string("in ") + (open_min ? "(" : "[") + format_number(min) + ", " +
           format_number(max) + (open_max ? ")" : "]");
  if (low) return (open_min ? "> " : ">= ") + format_number(min);
  if (high) return (open_max ? "< " : "<= ") + format_number(max);
  return "any";
}

std::string Bounds::words() const {
  const bool low = std::isfinite(min), high = std::isfinite(max);
  if (low && !high) {
    if (open_min) return min == 0 ? "positive" : "above " + format_number(min);
    return "at least " + format_number(min);
  }
  if (high && !low) return (open_max ? "below " : "at most ") + format_number(max);
  return symbols();
}

}  // namespace sdog
