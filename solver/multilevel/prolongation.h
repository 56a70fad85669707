#pragma once
// Coarse to fine: carries coarse positions (or displacements) to the fine mesh. A fine link vertex
// copies its coarse twin, an I vertex takes the midpoint of its coarse edge, an X vertex the centre
// of its coarse quad. A fine vertex with none of these (near a crease, where the coarse edge or
// quad lies in another patch) uses the rule of the nearest such vertex of its own patch in the flat
// sheet. The map is linear: fine = P coarse, P with one row per fine vertex.
#include <Eigen/Sparse>
#include <utility>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "solver/terms/term.h"

namespace sdog {

class Prolongation {
 public:
  /// The model must have its coarse mesh.
  explicit Prolongation(const DogModel& model);
  /// Fine positions for coarse positions (both as Dofs).
  Dofs apply(const Dofs& coarse) const;
  /// Fine vertex v as a weighted sum of coarse vertices.
  std::vector<std::pair<int, double>> row(int v) const;

 private:
  Eigen::SparseMatrix<double, Eigen::RowMajor> P_;  // fine vertices x coarse vertices
};

}  // namespace sdog
