#include "solver/terms/edge_angles.h"

#include <cmath>

namespace sdog {

double crease_edge_cosine(double alpha, double theta) {
  const double c = std::cos(alpha), s = std::sin(alpha);
  return c * c + s * s * std::cos(theta);
}

int EdgeAngleTerm::add(int v1, int v2, int w1, int w2, double rest_length_product, double cos_target) {
  add_block({v1, v2, w1, w2}, 1);
  rest_.push_back(rest_length_product);
  cos_.push_back(cos_target);
  return block_count() - 1;
}

void EdgeAngleTerm::clear() {
  clear_blocks();
  rest_.clear();
  cos_.clear();
}

void EdgeAngleTerm::evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const {
  const Eigen::Vector3d ev = p[0] - p[1], ew = p[2] - p[3];
  r[0] = ev.dot(ew) / rest_[b] - cos_[b];
  if (!J) return;
  for (int c = 0; c < 3; ++c) {
    J[c] = ew[c] / rest_[b];
    J[3 + c] = -ew[c] / rest_[b];
    J[6 + c] = ev[c] / rest_[b];
    J[9 + c] = -ev[c] / rest_[b];
  }
}

void EdgeAngleTerm::add_second_order(int b, const Eigen::Vector3d*, const double* y, double* H) const {
  // d2r/dv_i dw_j = s_i s_j I / rest, s = (+1, -1).
  const double s = y[0] / rest_[b];
  const int v_slot[2] = {0, 1}, w_slot[2] = {2, 3};
  const double sign[2] = {1, -1};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int c = 0; c < 3; ++c) {
        const double h = s * sign[i] * sign[j];
        H[(3 * v_slot[i] + c) * 12 + 3 * w_slot[j] + c] += h;
        H[(3 * w_slot[j] + c) * 12 + 3 * v_slot[i] + c] += h;
      }
}

}  // namespace sdog
