#pragma once
// What the run log and the frames report about a state x, the same for every solver mode:
// objective and its unweighted terms, DOG constraint residuals, stitching gaps, edge strain, and
// per-vertex/per-quad fields for pictures.
#include <array>
#include <vector>

#include "solver/problem/dog_problem.h"

namespace sdog {

struct Diagnostics {
  double objective = 0;                     ///< weighted, with the problem's current weights
  std::array<double, kTermCount> terms{};   ///< unweighted sum of squared residuals per term
  double dog_max = 0;                       ///< |c|_inf of the DOG constraints
  double dog_l2 = 0;                        ///< |c|_2
  double stitch_gap_max = 0;                ///< largest distance between two copies of a crease point
  double edge_strain_max = 0;               ///< largest |length / rest length - 1| over quad edges
};

Diagnostics diagnose(const DogProblem& problem, const Dofs& x);

/// Weighted objective only.
double weighted_objective(const DogProblem& problem, const Dofs& x);

struct Fields {
  std::vector<double> dog_residual;       ///< per vertex: largest |c| of its constraint rows
  std::vector<double> bending;            ///< per vertex: |r|^2 of its bending block
  std::vector<double> position_residual;  ///< per vertex: distance to its target (0 if free)
  std::vector<double> edge_strain;        ///< per quad: largest |length / rest - 1| of its edges
  /// per crease point: max over its stitching pairs (a, b) of |p_a - p_b|, p = t x_v1 + (1 - t) x_v2
  /// the position of a copy (its largest value is Diagnostics::stitch_gap_max)
  std::vector<double> stitch_gap;
};
Fields fields(const DogProblem& problem, const Dofs& x);

}  // namespace sdog
