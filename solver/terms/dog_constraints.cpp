#include "solver/terms/dog_constraints.h"

#include <algorithm>

namespace sdog {

DogConstraints::DogConstraints(const QuadTopology& topology) {
  const int n = static_cast<int>(topology.vertex_class.size());
  for (int v = 0; v < n; ++v) {
    const auto& nb = topology.neighbors[v];
    if (topology.vertex_class[v] == VertexClass::kStar) {
      add_block({v, nb[0], nb[1], nb[2], nb[3]}, 3);
      first_row_.push_back(rows_);
      rows_ += 3;
    } else if (topology.vertex_class[v] == VertexClass::kBnd3) {
      int missing = 0;
      while (nb[missing] >= 0) ++missing;
      add_block({v, nb[(missing + 1) % 4], nb[(missing + 2) % 4], nb[(missing + 3) % 4]}, 1);
      first_row_.push_back(rows_);
      rows_ += 1;
    }
  }
}

namespace {

// Row = sum over its cosine pairs (a, b) of sign * cos(e_a, e_b), e_j = p0 - p_{j+1}.
struct CosinePair {
  int a, b, row;
  double sign;
};

int cosine_pairs(int k, CosinePair* out) {
  if (k == 4) {
    const CosinePair pairs[6] = {{0, 1, 0, 1},  {1, 2, 0, -1}, {1, 2, 1, 1},
                                 {2, 3, 1, -1}, {2, 3, 2, 1},  {3, 0, 2, -1}};
    std::copy(pairs, pairs + 6, out);
    return 6;
  }
  out[0] = {0, 1, 0, 1};
  out[1] = {1, 2, 0, -1};
  return 2;
}

}  // namespace

void DogConstraints::evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const {
  const int k = block_size(b) - 1, rows = residual_count(b), cols = 3 * (k + 1);
  Eigen::Vector3d e[4];
  for (int j = 0; j < k; ++j) e[j] = p[0] - p[j + 1];
  std::fill(r, r + rows, 0.0);
  if (J) std::fill(J, J + rows * cols, 0.0);
  CosinePair pairs[6];
  const int np = cosine_pairs(k, pairs);
  for (int q = 0; q < np; ++q) {
    const auto& cp = pairs[q];
    if (!J) {
      r[cp.row] += cp.sign * cosine_value(e[cp.a], e[cp.b]);
      continue;
    }
    const CosineDerivatives d = cosine_derivatives(e[cp.a], e[cp.b], false);
    r[cp.row] += cp.sign * d.value;
    double* row = J + cp.row * cols;
    // de/dp0 = I, de_j/dp_{j+1} = -I.
    for (int c = 0; c < 3; ++c) {
      row[c] += cp.sign * (d.du[c] + d.dv[c]);
      row[3 * (cp.a + 1) + c] -= cp.sign * d.du[c];
      row[3 * (cp.b + 1) + c] -= cp.sign * d.dv[c];
    }
  }
}

void DogConstraints::add_second_order(int b, const Eigen::Vector3d* p, const double* y,
                                      double* H) const {
  const int k = block_size(b) - 1, cols = 3 * (k + 1);
  Eigen::Vector3d e[4];
  for (int j = 0; j < k; ++j) e[j] = p[0] - p[j + 1];
  CosinePair pairs[6];
  const int np = cosine_pairs(k, pairs);
  for (int q = 0; q < np; ++q) {
    const auto& cp = pairs[q];
    const double s = cp.sign * y[cp.row];
    if (s == 0) continue;
    const CosineDerivatives d = cosine_derivatives(e[cp.a], e[cp.b], true);
    // q = (p0, p_a, p_b): e_a = p0 - p_a, e_b = p0 - p_b. Vertex slots and signs of de/dq:
    const int slot[3] = {0, cp.a + 1, cp.b + 1};
    const double du_sign[3] = {1, -1, 0}, dv_sign[3] = {1, 0, -1};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const Eigen::Matrix3d block =
            du_sign[i] * du_sign[j] * d.duu + du_sign[i] * dv_sign[j] * d.duv +
            dv_sign[i] * du_sign[j] * d.duv.transpose() + dv_sign[i] * dv_sign[j] * d.dvv;
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            H[(3 * slot[i] + r) * cols + 3 * slot[j] + c] += s * block(r, c);
      }
  }
}

}  // namespace sdog
