#pragma once
// The targets of a problem's soft constraints that a scenario or the user moves: the position
// targets and the dihedral-angle cosines. The standard solver's continuation (standard_mode.h)
// moves them from the targets a state has reached towards the requested ones in sub-steps.
#include <Eigen/Core>
#include <vector>

#include "solver/problem/dog_problem.h"

namespace sdog {

struct Targets {
  std::vector<Eigen::Vector3d> positions;
  std::vector<double> cosines;

  /// The problem's current targets.
  static Targets of(const DogProblem& problem);
  /// The targets that x meets exactly (each term's value at x: target plus residual).
  static Targets met_by(const DogProblem& problem, const Dofs& x);
  void install(DogProblem& problem) const;
  /// Same number of position and angle targets.
  bool matches(const Targets& other) const;
  /// (1 - s) this + s other (same layout).
  Targets towards(const Targets& other, double s) const;
  /// Largest difference of a position (mesh units) or a cosine.
  double distance(const Targets& other) const;
};

}  // namespace sdog
