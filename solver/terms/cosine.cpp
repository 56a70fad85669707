#include "solver/terms/cosine.h"

namespace sdog {

CosineDerivatives cosine_derivatives(const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                                     bool second) {
  CosineDerivatives d;
  const double nu = u.norm(), nv = v.norm();
  const double c = d.value = cosine_value(u, v);
  d.du = v / (nu * nv) - c * u / (nu * nu);
  d.dv = u / (nu * nv) - c * v / (nv * nv);
  if (!second) return d;
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double nu2 = nu * nu, nv2 = nv * nv;
  d.duu = -(v * u.transpose() + u * v.transpose()) / (nu2 * nu * nv) +
          3 * c * u * u.transpose() / (nu2 * nu2) - c * I / nu2;
  d.dvv = -(u * v.transpose() + v * u.transpose()) / (nv2 * nv * nu) +
          3 * c * v * v.transpose() / (nv2 * nv2) - c * I / nv2;
  d.duv = I / (nu * nv) - v * v.transpose() / (nu * nv2 * nv) -
          u * u.transpose() / (nu2 * nu * nv) + c * u * v.transpose() / (nu2 * nv2);
  return d;
}

}  // namespace sdog
