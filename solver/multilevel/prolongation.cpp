#include "solver/multilevel/prolongation.h"

#include <limits>
#include <stdexcept>

namespace sdog {

Prolongation::Prolongation(const DogModel& model) {
  if (!model.has_coarse) throw std::logic_error("Prolongation: the model has no coarse mesh");
  const DogMesh& fine = model.fine;
  const FineCoarseMap& map = model.map;
  const int n = fine.vertex_count();
  std::vector<std::vector<std::pair<int, double>>> rows(n);
  std::vector<bool> mapped(n);
  for (int v = 0; v < n; ++v) {
    if (map.fine_to_coarse[v] >= 0) {
      rows[v] = {{map.fine_to_coarse[v], 1.0}};
    } else if (map.fine_to_coarse_edge[v][0] >= 0 && map.fine_to_coarse_edge[v][1] >= 0) {
      rows[v] = {{map.fine_to_coarse_edge[v][0], 0.5}, {map.fine_to_coarse_edge[v][1], 0.5}};
    } else if (map.fine_to_coarse_quad[v] >= 0) {
      for (int k = 0; k < 4; ++k)
        rows[v].push_back({model.coarse.F(map.fine_to_coarse_quad[v], k), 0.25});
    }
    mapped[v] = !rows[v].empty();
  }
  for (int p = 0; p < fine.patch_count(); ++p) {
    const int begin = fine.patch_begin[p], end = fine.patch_begin[p + 1];
    for (int v = begin; v < end; ++v) {
      if (mapped[v]) continue;
      int nearest = -1;
      double best = std::numeric_limits<double>::infinity();
      for (int u = begin; u < end; ++u) {
        const double d = (fine.V.row(u) - fine.V.row(v)).squaredNorm();
        if (mapped[u] && d < best) {
          best = d;
          nearest = u;
        }
      }
      if (nearest < 0)
        throw std::logic_error("Prolongation: fine patch " + std::to_string(p) +
                               " has no mapped vertex");
      rows[v] = rows[nearest];
    }
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (int v = 0; v < n; ++v)
    for (const auto& [c, w] : rows[v]) entries.emplace_back(v, c, w);
  P_.resize(n, model.coarse.vertex_count());
  P_.setFromTriplets(entries.begin(), entries.end());
}

Dofs Prolongation::apply(const Dofs& coarse) const {
  const Eigen::MatrixX3d fine = P_ * to_positions(coarse);
  Dofs x(3 * fine.rows());
  for (Eigen::Index v = 0; v < fine.rows(); ++v) x.segment<3>(3 * v) = fine.row(v).transpose();
  return x;
}

std::vector<std::pair<int, double>> Prolongation::row(int v) const {
  std::vector<std::pair<int, double>> r;
  for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(P_, v); it; ++it)
    r.push_back({static_cast<int>(it.col()), it.value()});
  return r;
}

}  // namespace sdog
