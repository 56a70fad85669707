#pragma once
// The cosine of the angle between two vectors and its first and second derivatives:
//   c = u.v / (|u| |v|)
//   dc/du = v / (|u||v|) - c u / |u|^2
//   d2c/du2 = -(v u^T + u v^T) / (|u|^3 |v|) + 3 c u u^T / |u|^4 - c I / |u|^2
//   d2c/dudv = I / (|u||v|) - v v^T / (|u||v|^3) - u u^T / (|u|^3 |v|) + c u v^T / (|u|^2 |v|^2)
// (and symmetrically in v).
#include <Eigen/Core>

namespace sdog {

struct CosineDerivatives {
  double value = 0;
  Eigen::Vector3d du, dv;
  Eigen::Matrix3d duu, duv, dvv;  ///< filled only when asked for
};

CosineDerivatives cosine_derivatives(const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                                     bool second);

/// The value alone (cosine_derivatives' value is this one): constraint values are evaluated many
/// times per iteration (line searches, restoration), without derivatives.
inline double cosine_value(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  return u.dot(v) / (u.norm() * v.norm());
}

/// The same cosine for any scalar type (automatic differentiation in tests).
template <class T>
T cosine(const T* u, const T* v) {
  using std::sqrt;
  const T uv = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const T uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  const T vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  return uv / sqrt(uu * vv);
}

}  // namespace sdog
