#pragma once
// Small statistics of measured values.
#include <optional>
#include <vector>

namespace sdog {

/// The median (the upper median for even sizes; 0 when empty).
double median(std::vector<double> values);

/// The median over k of reference[k] / values[k] (each ratio of two measurements made one shortly
/// after the other); empty unless both have the same, non-zero number of values.
std::optional<double> paired_ratio(const std::vector<double>& reference,
                                   const std::vector<double>& values);

}  // namespace sdog
