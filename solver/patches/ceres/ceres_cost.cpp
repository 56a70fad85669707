#include "solver/patches/ceres/ceres_cost.h"

#include <cmath>
#include <vector>

namespace sdog {

TermCost::TermCost(const Term& term, int block, double weight, const double* offset)
    : term_(term), block_(block), scale_(std::sqrt(weight)), offset_(offset) {
  set_num_residuals(term.residual_count(block));
  for (int j = 0; j < term.block_size(block); ++j) mutable_parameter_block_sizes()->push_back(3);
}

void TermCost::set_weight(double weight) {
  scale_ = std::sqrt(weight);
}

bool TermCost::Evaluate(double const* const* parameters, double* residuals,
                        double** jacobians) const {
  const int k = term_.block_size(block_), m = term_.residual_count(block_), cols = 3 * k;
  std::vector<Eigen::Vector3d> p(k);
  for (int j = 0; j < k; ++j) p[j] = Eigen::Map<const Eigen::Vector3d>(parameters[j]);
  std::vector<double> J(jacobians ? static_cast<size_t>(m) * cols : 0);
  term_.evaluate(block_, p.data(), residuals, jacobians ? J.data() : nullptr);
  for (int i = 0; i < m; ++i) residuals[i] = scale_ * (residuals[i] - (offset_ ? offset_[i] : 0.0));
  if (!jacobians) return true;
  for (int j = 0; j < k; ++j) {
    if (!jacobians[j]) continue;
    for (int i = 0; i < m; ++i)
      for (int c = 0; c < 3; ++c) jacobians[j][i * 3 + c] = scale_ * J[i * cols + 3 * j + c];
  }
  return true;
}

}  // namespace sdog
