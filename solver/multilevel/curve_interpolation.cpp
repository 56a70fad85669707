#include "solver/multilevel/curve_interpolation.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sdog {

Eigen::Vector3d crease_point_mean(const DogMesh& mesh, const Eigen::MatrixX3d& X, int point) {
  const auto& copies = mesh.stitching.points[point].copies;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const EdgePoint& e : copies) sum += DogMesh::position(X, e);
  return sum / static_cast<double>(copies.size());
}

Eigen::Vector3d interpolate(const DogMesh& coarse, const Eigen::MatrixX3d& X,
                            const CurveStencil& s) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int i = 0; i < s.count; ++i) p += s.weights[i] * crease_point_mean(coarse, X, s.points[i]);
  return p;
}

namespace {

// Lagrange weights at u of the nodes s[0..n).
std::array<double, 4> lagrange(const std::array<double, 4>& s, int n, double u) {
  std::array<double, 4> w{};
  for (int i = 0; i < n; ++i) {
    w[i] = 1;
    for (int j = 0; j < n; ++j)
      if (j != i) w[i] *= (u - s[j]) / (s[i] - s[j]);
  }
  return w;
}

}  // namespace

std::vector<std::vector<CurveStencil>> coarse_curve_stencils(const DogModel& model) {
  const DogMesh& coarse = model.coarse;
  std::vector<std::vector<CurveStencil>> result(model.map.curves.size());
  for (size_t c = 0; c < model.map.curves.size(); ++c) {
    const auto& curve = coarse.stitching.curves[c];
    const int n = static_cast<int>(curve.points.size());
    if (n == 0) continue;
    // Flat arc length (chord lengths at rest) at every coarse point; closed curves wrap.
    std::vector<double> arc(n + 1, 0.0);
    for (int i = 1; i <= n; ++i)
      arc[i] = arc[i - 1] + (crease_point_mean(coarse, coarse.V, curve.points[i % n]) -
                             crease_point_mean(coarse, coarse.V, curve.points[i - 1]))
                                .norm();
    const double total = arc[n];
    auto param = [&](int i) {  // parameter of (unwrapped) index i
      if (!curve.closed) return arc[i];
      const int wraps = (i >= 0 ? i / n : -((n - 1 - i) / n));
      return arc[i - wraps * n] + wraps * total;
    };
    const int m = std::min(n, 4);
    for (const auto& cp : model.map.curves[c]) {
      CurveStencil st;
      if (cp.coarse >= 0) {
        st.count = 1;
        st.points[0] = curve.points[cp.coarse];
        st.weights[0] = 1;
      } else {
        if (cp.segment < 0)  // the alternative coarse DOG (alt_coarse.h) keeps no crease end
          throw std::logic_error("fine crease point of crease " + std::to_string(c) +
                                 " has no coarse points to interpolate between");
        const double u =
            param(cp.segment) + cp.fraction * (param(cp.segment + 1) - param(cp.segment));
        int first = cp.segment - (m - 1) / 2;  // nodes around the segment
        if (!curve.closed) first = std::clamp(first, 0, n - m);
        std::array<double, 4> s{};
        st.count = m;
        for (int i = 0; i < m; ++i) {
          const int j = first + i;
          s[i] = param(j);
          st.points[i] = curve.points[((j % n) + n) % n];
        }
        st.weights = lagrange(s, m, u);
      }
      result[c].push_back(st);
    }
  }
  return result;
}

}  // namespace sdog
