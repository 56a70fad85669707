#pragma once
// The targets of a problem's soft constraints that a scenario or the user moves: the position
// targets and the signed dihedral angles. The standard solver's continuation (standard_mode.h)
// moves them from the targets a state has reached towards the requested ones in sub-steps.
#include <Eigen/Core>
#include <vector>

#include "solver/problem/dog_problem.h"

namespace sdog {

/// How far one continuation sub-step may move the targets: a position by `length` (mesh units), a
/// dihedral angle by `angle` (radians) where the crease crosses its grid edge at right angles
/// (elsewhere by angle / sin^2(alpha), as the angle rows scale with sin^2(alpha)).
struct TargetSteps {
  double length = 1;
  double angle = 1;
};

struct Targets {
  std::vector<Eigen::Vector3d> positions;
  std::vector<double> angles;  ///< radians
  /// sin^2(alpha) of each angle target (how much its rows weigh; dihedral_angles.h).
  std::vector<double> angle_scales;

  /// The problem's current targets.
  static Targets of(const DogProblem& problem);
  /// The targets that x meets exactly (each term's value at x: target plus residual; the angle
  /// each angle block measures).
  static Targets met_by(const DogProblem& problem, const Dofs& x);
  void install(DogProblem& problem) const;
  /// Same number of position and angle targets.
  bool matches(const Targets& other) const;
  /// (1 - s) this + s other (same layout).
  Targets towards(const Targets& other, double s) const;
  /// How many sub-steps of size `steps` the motion to `other` takes at least: the largest
  /// |position difference| / steps.length and sin^2(alpha) |angle difference| / steps.angle.
  double distance(const Targets& other, const TargetSteps& steps) const;
};

}  // namespace sdog
