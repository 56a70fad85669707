#pragma once
// Fold bias (folding mode): at every curved fold site,
//   r = tanh(k B.e1) + tanh(k B.e2),   B = (p_prev - p) x (p_next - p),  k = 1000,
// with p, p_prev, p_next crease points (first copies) and e1, e2 the two copies of the crossing
// edge. Minimising r^2 pushes the copies to opposite sides of the osculating plane (folded).
// Gauss-Newton Hessian only, as in the reference.
#include <array>

#include "solver/terms/crease_geometry.h"
#include "solver/terms/term.h"

namespace sdog {

/// The sharpness k of the standard solver's fold bias (the reference's).
constexpr double kFoldSharpness = 1000;

class FoldBiasTerm : public Term {
 public:
  FoldBiasTerm(const DogMesh& mesh, const std::vector<FoldSite>& sites,
               double sharpness = kFoldSharpness);
  double sharpness() const { return sharpness_; }
  const char* name() const override { return "fold_bias"; }

  template <class T>
  void residual(int b, const T* const* p, T* r) const {
    using std::tanh;
    const Site& s = sites_[b];
    T P[3], Pb[3], Pf[3], a[3], f[3], B[3];
    for (int c = 0; c < 3; ++c) {
      P[c] = s.t[0] * p[s.slot[0]][c] + (1 - s.t[0]) * p[s.slot[1]][c];
      Pb[c] = s.t[2] * p[s.slot[4]][c] + (1 - s.t[2]) * p[s.slot[5]][c];
      Pf[c] = s.t[3] * p[s.slot[6]][c] + (1 - s.t[3]) * p[s.slot[7]][c];
      a[c] = Pb[c] - P[c];
      f[c] = Pf[c] - P[c];
    }
    B[0] = a[1] * f[2] - a[2] * f[1];
    B[1] = a[2] * f[0] - a[0] * f[2];
    B[2] = a[0] * f[1] - a[1] * f[0];
    T s1 = T(0), s2 = T(0);
    for (int c = 0; c < 3; ++c) {
      s1 += B[c] * (p[s.slot[0]][c] - p[s.slot[1]][c]);
      s2 += B[c] * (p[s.slot[2]][c] - p[s.slot[3]][c]);
    }
    r[0] = tanh(sharpness_ * s1) + tanh(sharpness_ * s2);
  }

  void evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const override;

 private:
  // Roles: 0,1 = v1, v2 (copy 1, also the crease point p = t v1 + (1-t) v2); 2,3 = w1, w2 (copy 2);
  // 4,5 = previous point's edge; 6,7 = next point's edge. slot[role] = index in the block.
  struct Site {
    std::array<int, 8> slot;
    std::array<double, 4> t;  // p, (unused), previous, next
  };
  std::vector<Site> sites_;
  double sharpness_;
};

}  // namespace sdog
