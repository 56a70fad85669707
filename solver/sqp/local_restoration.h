#pragma once
// Local constraint restoration. After a global step of the SQP solver the few constraint rows still
// above the tolerance are usually concentrated in small regions (a dragged corner, a strongly bent
// crease). Fixing them with another global factorisation costs as much as the whole step; instead
// only the vertices near the violated rows move: the vertices of their blocks plus `rings` rings
// of DOG neighbours. On that neighbourhood F the restoration step of the global solver is solved
// exactly, with everything else held:
//     (H_FF + rho J_RF^T J_RF + delta I) d_F = -rho J_RF^T c_R,
// R = every constraint row whose block touches F, H_FF the objective Hessian restricted to F
// (the metric of the step), J_RF the constraint Jacobian restricted to R x F.
#include <Eigen/Sparse>
#include <vector>

#include "solver/terms/term.h"

namespace sdog {

class LocalRestoration {
 public:
  /// `constraints`: the constraint term (one block per constrained vertex) over `vertex_count`
  /// vertices.
  LocalRestoration(int vertex_count, const Term& constraints, int rings = 2);

  /// Vertices that move to fix the rows with |c_i| > tolerance (sorted; empty when none).
  std::vector<int> neighbourhood(const Eigen::VectorXd& c, double tolerance) const;

  /// The step d (3n, zero outside the neighbourhood) for constraint values c and Jacobian J at the
  /// current point; H is the lower triangle of the objective Hessian (3n x 3n). Returns false when
  /// the neighbourhood is empty or the local factorisation fails.
  bool step(const std::vector<int>& vertices, const Eigen::VectorXd& c,
            const Eigen::SparseMatrix<double, Eigen::RowMajor>& J,
            const Eigen::SparseMatrix<double>& H, double rho, double delta,
            Eigen::VectorXd& d) const;

 private:
  const Term& constraints_;
  int rings_;
  std::vector<int> row_block_;                   // constraint row -> block
  std::vector<int> first_row_;                   // block -> first row
  std::vector<std::vector<int>> vertex_blocks_;  // vertex -> blocks containing it
};

}  // namespace sdog
