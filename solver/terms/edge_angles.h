#pragma once
// Edge angle constraints (cosine form, soft): between edges (v1, v2) and (w1, w2) with their rest
// lengths frozen,
//   r = (v1 - v2).(w1 - w2) / (l_v l_w) - cos(phi).
// At a crease point the two edges are the copies of the grid edge the crease crosses, one per
// patch, and a dihedral angle theta at the crease asks for
//   cos(phi) = cos^2(alpha) + sin^2(alpha) cos(theta)
// where alpha is the angle between the crease tangent and the grid edge in the flat state.
#include "solver/terms/term.h"

namespace sdog {

/// cos(phi) between the two copies of a grid edge crossing a crease at angle alpha when the
/// crease is folded to dihedral angle theta (radians; theta = 0 is flat).
double crease_edge_cosine(double alpha, double theta);

class EdgeAngleTerm : public Term {
 public:
  const char* name() const override { return "angles"; }
  /// Adds an angle constraint; returns its block index.
  int add(int v1, int v2, int w1, int w2, double rest_length_product, double cos_target);
  void set_cos(int b, double c) { cos_[b] = c; }
  double cos_target(int b) const { return cos_[b]; }
  void clear();

  // Block vertices (v1, v2, w1, w2).
  template <class T>
  void residual(int b, const T* const* p, T* r) const {
    T dot = T(0);
    for (int c = 0; c < 3; ++c) dot += (p[0][c] - p[1][c]) * (p[2][c] - p[3][c]);
    r[0] = dot / rest_[b] - cos_[b];
  }

  void evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const override;
  bool has_second_order() const override { return true; }
  void add_second_order(int b, const Eigen::Vector3d* p, const double* y, double* H) const override;

 private:
  std::vector<double> rest_, cos_;
};

}  // namespace sdog
