#pragma once
// Isometry: one residual per quad edge (i, j), r = |p_i - p_j|^2 - l0^2 with l0 the rest length.
// Second derivatives: Hessian(r) = 2 [I -I; -I I]; the exact Hessian of r^2 uses y = max(r, 0) so
// that it stays positive semi-definite when the edge is compressed (as in the reference).
#include "geometry/mesh/quad_topology.h"
#include "solver/terms/term.h"

namespace sdog {

class IsometryTerm : public Term {
 public:
  IsometryTerm(const QuadTopology& topology, const Dofs& rest);
  const char* name() const override { return "isometry"; }

  template <class T>
  void residual(int b, const T* const* p, T* r) const {
    T d2 = T(0);
    for (int c = 0; c < 3; ++c) d2 += (p[0][c] - p[1][c]) * (p[0][c] - p[1][c]);
    r[0] = d2 - rest_squared_[b];
  }

  void evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const override;
  bool has_second_order() const override { return true; }
  void add_second_order(int b, const Eigen::Vector3d* p, const double* y, double* H) const override;
  void curvature_weights(int b, const double* r, double* y) const override;
  /// Number of edges |E| (the default weight is 20000 / |E|).
  int edge_count() const { return block_count(); }
  double rest_length(int b) const { return std::sqrt(rest_squared_[b]); }

 private:
  std::vector<double> rest_squared_;
};

}  // namespace sdog
