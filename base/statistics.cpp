#include "base/statistics.h"

#include <algorithm>

namespace sdog {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

std::optional<double> paired_ratio(const std::vector<double>& reference,
                                   const std::vector<double>& values) {
  if (values.empty() || values.size() != reference.size()) return std::nullopt;
  std::vector<double> ratios;
  for (size_t k = 0; k < values.size(); ++k) ratios.push_back(reference[k] / values[k]);
  return median(ratios);
}

}  // namespace sdog
