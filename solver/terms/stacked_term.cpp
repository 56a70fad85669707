#include "solver/terms/stacked_term.h"

#include <algorithm>
#include <vector>

namespace sdog {

StackedTerm::StackedTerm(std::vector<Part> parts) : parts_(std::move(parts)) {
  for (const Part& part : parts_) {
    first_.push_back(block_count());
    const Term& t = *part.term;
    for (int b = 0; b < t.block_count(); ++b)
      add_block(t.block_vertices(b), t.block_size(b), t.residual_count(b));
  }
}

std::pair<const StackedTerm::Part*, int> StackedTerm::locate(int b) const {
  const size_t k =
      static_cast<size_t>(std::upper_bound(first_.begin(), first_.end(), b) - first_.begin()) - 1;
  return {&parts_[k], b - first_[k]};
}

void StackedTerm::evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const {
  const auto [part, local] = locate(b);
  part->term->evaluate(local, p, r, J);
  if (part->scale == 1) return;
  const int m = residual_count(b);
  for (int i = 0; i < m; ++i) r[i] *= part->scale;
  if (J)
    for (int i = 0; i < m * 3 * block_size(b); ++i) J[i] *= part->scale;
}

bool StackedTerm::is_linear() const {
  return std::all_of(parts_.begin(), parts_.end(),
                     [](const Part& p) { return p.term->is_linear(); });
}

bool StackedTerm::has_second_order() const {
  return std::any_of(parts_.begin(), parts_.end(),
                     [](const Part& p) { return p.term->has_second_order(); });
}

void StackedTerm::add_second_order(int b, const Eigen::Vector3d* p, const double* y,
                                   double* H) const {
  const auto [part, local] = locate(b);
  if (part->scale == 1) {
    part->term->add_second_order(local, p, y, H);
    return;
  }
  // sum_i y_i Hess(s r_i) = sum_i (s y_i) Hess(r_i)
  std::vector<double> scaled(y, y + residual_count(b));
  for (double& v : scaled) v *= part->scale;
  part->term->add_second_order(local, p, scaled.data(), H);
}

void StackedTerm::curvature_weights(int b, const double* r, double* y) const {
  const auto [part, local] = locate(b);
  part->term->curvature_weights(local, r, y);
}

}  // namespace sdog
