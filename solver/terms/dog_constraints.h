#pragma once
// The DOG constraints, the only hard constraints (normalised cosine form). With e_k = p0 - p_k
// for the neighbours of p0 in cyclic order (xf, yf, xb, yb) and cos(a, b) the cosine between
// e_a and e_b:
//   star (3 rows): c1 = cos(xf,yf) - cos(yf,xb), c2 = cos(yf,xb) - cos(xb,yb),
//                  c3 = cos(xb,yb) - cos(yb,xf)          (the four angles are equal)
//   bnd3 (1 row):  c = cos(b1, in) - cos(in, b2)         (b1, b2 on the boundary, `in` inside)
// bnd2 and bnd4 vertices are unconstrained. Value, Jacobian and second derivatives all come
// from this one definition (the reference mixed a rescaled Jacobian with unscaled values).
#include "geometry/mesh/quad_topology.h"
#include "solver/terms/cosine.h"
#include "solver/terms/term.h"

namespace sdog {

class DogConstraints : public Term {
 public:
  explicit DogConstraints(const QuadTopology& topology);
  const char* name() const override { return "dog"; }

  /// Total number of constraint rows (3 per star, 1 per bnd3).
  int row_count() const { return rows_; }
  /// First global row of block b.
  int first_row(int b) const { return first_row_[b]; }

  // Block vertices: star (p0, xf, yf, xb, yb); bnd3 (p0, b1, in, b2).
  template <class T>
  void residual(int b, const T* const* p, T* r) const {
    const int k = block_size(b) - 1;
    T e[4][3];
    for (int j = 0; j < k; ++j)
      for (int c = 0; c < 3; ++c) e[j][c] = p[0][c] - p[j + 1][c];
    if (k == 4) {
      const T c01 = cosine(e[0], e[1]), c12 = cosine(e[1], e[2]), c23 = cosine(e[2], e[3]),
              c30 = cosine(e[3], e[0]);
      r[0] = c01 - c12;
      r[1] = c12 - c23;
      r[2] = c23 - c30;
    } else {
      r[0] = cosine(e[0], e[1]) - cosine(e[1], e[2]);
    }
  }

  void evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const override;
  bool has_second_order() const override { return true; }
  void add_second_order(int b, const Eigen::Vector3d* p, const double* y, double* H) const override;

 private:
  std::vector<int> first_row_;
  int rows_ = 0;
};

}  // namespace sdog
