#include "solver/multilevel/restriction.h"

#include "solver/terms/crease_geometry.h"

#include <Eigen/QR>
#include <algorithm>
#include <stdexcept>

namespace sdog {
namespace {

constexpr int kFitPoints = 12;  // fine vertices per quadratic fit

Eigen::Matrix<double, 1, 6> basis(double X, double Y) {
  Eigen::Matrix<double, 1, 6> b;
  b << 1, X, Y, X * X, X * Y, Y * Y;
  return b;
}

// The least-squares quadratic map from the flat positions of the fine vertices `near` to their
// positions in fine_x, evaluated at the flat point (X, Y).
Eigen::Vector3d extrapolate(const DogMesh& fine, const std::vector<int>& near, const Dofs& fine_x,
                            double X, double Y) {
  Eigen::MatrixXd M(near.size(), 6);
  Eigen::MatrixXd P(near.size(), 3);
  for (size_t k = 0; k < near.size(); ++k) {
    M.row(k) =
        basis(fine.V(near[k], 0) - X, fine.V(near[k], 1) - Y);  // centred: the value is row 0
    P.row(k) = vertex_of(fine_x, near[k]).transpose();
  }
  const Eigen::MatrixXd A = M.colPivHouseholderQr().solve(P);  // 6 x 3
  return A.row(0).transpose();
}

// Moves the coarse-only vertices so that the coarse crease points land on their fine twins: for
// every copy t x_v1 + (1 - t) x_v2 = P (P the fine crease point, the mean of its copies) with one
// coarse-only end u and the other end known, least squares in u together with a weak pull
// (kPrior) towards the extrapolated position. The fold test and fold bias measure the crease's
// osculating plane from second differences of crease points: extrapolation errors of 1e-2 turned
// it over at slightly folded creases.
void match_crease_points(const DogModel& model, const Dofs& fine_x, Dofs& x) {
  constexpr double kPrior = 0.01;
  const DogMesh& coarse = model.coarse;
  const auto& twin = model.map.coarse_to_fine;
  std::vector<double> a(coarse.vertex_count(), 0.0);
  std::vector<Eigen::Vector3d> b(coarse.vertex_count(), Eigen::Vector3d::Zero());
  const std::vector<int> crease_twin = coarse_crease_twins(model);
  for (const auto& curve : model.fine.stitching.curves)
    for (int f : curve.points) {
      if (crease_twin[f] < 0) continue;
      Eigen::Vector3d P = Eigen::Vector3d::Zero();
      const auto& fine_copies = model.fine.stitching.points[f].copies;
      for (const EdgePoint& e : fine_copies) P += edge_point_position(e, fine_x);
      P /= static_cast<double>(fine_copies.size());
      for (const EdgePoint& e : coarse.stitching.points[crease_twin[f]].copies) {
        const bool free1 = twin[e.v1] < 0, free2 = twin[e.v2] < 0;
        if (free1 == free2)
          continue;  // both ends known (a crease point at a link vertex) or both free
        const int u = free1 ? e.v1 : e.v2, known = free1 ? e.v2 : e.v1;
        const double w = free1 ? e.t : 1 - e.t;
        a[u] += w * w;
        b[u] += w * (P - (1 - w) * Eigen::Vector3d(vertex_of(x, known)));
      }
    }
  for (int u = 0; u < coarse.vertex_count(); ++u)
    if (a[u] > 0)
      x.segment<3>(3 * u) = (b[u] + kPrior * Eigen::Vector3d(vertex_of(x, u))) / (a[u] + kPrior);
}

}  // namespace

std::vector<int> coarse_crease_twins(const DogModel& model) {
  std::vector<int> twin(model.fine.stitching.points.size(), -1);
  const auto& fine_curves = model.fine.stitching.curves;
  const auto& coarse_curves = model.coarse.stitching.curves;
  for (size_t c = 0;
       c < fine_curves.size() && c < model.map.curves.size() && c < coarse_curves.size(); ++c)
    for (size_t k = 0; k < fine_curves[c].points.size() && k < model.map.curves[c].size(); ++k) {
      const int index = model.map.curves[c][k].coarse;
      if (index >= 0) twin[fine_curves[c].points[k]] = coarse_curves[c].points[index];
    }
  return twin;
}

Dofs restrict_to_coarse(const DogModel& model, const Dofs& fine_x) {
  if (!model.has_coarse) throw std::logic_error("restrict_to_coarse: the model has no coarse mesh");
  const DogMesh& coarse = model.coarse;
  const auto& twin = model.map.coarse_to_fine;
  Dofs x = Dofs::Zero(3 * coarse.vertex_count());
  for (int c = 0; c < coarse.vertex_count(); ++c)
    if (twin[c] >= 0) x.segment<3>(3 * c) = vertex_of(fine_x, twin[c]);
  const DogMesh& fine = model.fine;
  for (int p = 0; p < coarse.patch_count(); ++p) {  // patch ids match (fine_coarse_map.h)
    const int begin = fine.patch_begin[p], end = fine.patch_begin[p + 1];
    if (end - begin < kFitPoints)
      throw std::logic_error("restrict_to_coarse: fine patch " + std::to_string(p) +
                             " has fewer than " + std::to_string(kFitPoints) + " vertices");
    for (int c = coarse.patch_begin[p]; c < coarse.patch_begin[p + 1]; ++c) {
      if (twin[c] >= 0) continue;
      std::vector<int> near(end - begin);
      for (int v = begin; v < end; ++v) near[v - begin] = v;
      const auto distance = [&](int v) { return (fine.V.row(v) - coarse.V.row(c)).squaredNorm(); };
      std::partial_sort(near.begin(), near.begin() + kFitPoints, near.end(), [&](int a, int b) {
        return distance(a) < distance(b) || (distance(a) == distance(b) && a < b);
      });
      near.resize(kFitPoints);
      x.segment<3>(3 * c) = extrapolate(fine, near, fine_x, coarse.V(c, 0), coarse.V(c, 1));
    }
  }
  match_crease_points(model, fine_x, x);
  return x;
}

}  // namespace sdog
