#pragma once
// What the run log and the frames report about a state x, the same for every solver mode:
// objective and its unweighted terms, DOG constraint residuals, stitching gaps, edge strain, and
// per-vertex/per-quad fields for pictures.
#include <array>
#include <vector>

#include "solver/problem/dog_problem.h"

namespace sdog {

/// A fold site counts as bent (one way or the other) beyond this angle, degrees.
constexpr double kBentDegrees = 5;

/// A strain of the paper (|length / rest length - 1| of an edge in DogProblem::sheet_edges) above
/// this means the sheet visibly stretches or shrinks: paper does not, so a run that ends there
/// says so.
constexpr double kStretchedStrain = 0.05;

/// The signed difference angle - target wrapped into (-180, 180] degrees.
double angle_difference(double angle, double target);

/// The fold angles against the angle targets (problem.angles): of the fold sites with a nonzero
/// target, how many bend by more than kBentDegrees and how many of those bend the way their target
/// says; and the median |angle - target| over every site with a target (degrees). Sites within
/// kFoldTipRadius of a fold tip (geometry/pattern/fold_tips.h), where folds fade, are counted
/// apart.
struct AngleAgreement {
  int targeted_sites = 0, bent_sites = 0, bent_as_targeted = 0;
  int tip_sites = 0;    ///< sites with a nonzero target near a fold tip, not in the counts above
  int tip_against = 0;  ///< of them, bent by more than kBentDegrees against their target
  double median_error = 0;
  /// bent_as_targeted / bent_sites (1 when no site bends).
  double direction_agreement() const {
    return bent_sites > 0 ? double(bent_as_targeted) / bent_sites : 1.0;
  }
  /// Sites bent against their target (away from fold tips).
  int against() const { return bent_sites - bent_as_targeted; }
  /// Sites bent against their target, next to fold tips too.
  int all_against() const { return against() + tip_against; }
};
/// Whether the crease point `point` of `mesh` lies within kFoldTipRadius of a fold tip.
bool near_fold_tip(const DogMesh& mesh, int point);
/// Whether a site at `angle` degrees with a nonzero `target` bends by more than kBentDegrees the
/// other way.
bool bent_against(double angle, double target);
AngleAgreement angle_agreement(const DogProblem& problem, const Dofs& x);

struct Diagnostics {
  double objective = 0;                    ///< weighted, with the problem's current weights
  std::array<double, kTermCount> terms{};  ///< unweighted sum of squared residuals per term
  double dog_max = 0;                      ///< |c|_inf of the DOG constraints
  double dog_l2 = 0;                       ///< |c|_2
  double stitch_gap_max = 0;   ///< largest distance between two copies of a crease point
  double edge_strain_max = 0;  ///< largest |length / rest length - 1| over quad edges
  /// The same over the edges of the paper (DogProblem::sheet_edges), signed (< 0: shorter), and
  /// the patch of that edge (-1: none).
  double sheet_strain_max = 0;
  double sheet_strain_worst = 0;
  int sheet_strain_patch = -1;
  AngleAgreement angles_met;
};

Diagnostics diagnose(const DogProblem& problem, const Dofs& x);

/// Weighted objective only.
double weighted_objective(const DogProblem& problem, const Dofs& x);

struct Fields {
  std::vector<double> dog_residual;       ///< per vertex: largest |c| of its constraint rows
  std::vector<double> bending;            ///< per vertex: |r|^2 of its bending block
  std::vector<double> position_residual;  ///< per vertex: distance to its target (0 if free)
  std::vector<double> edge_strain;        ///< per quad: largest |length / rest - 1| of its edges
  /// per crease point: max over its stitching pairs (a, b) of |p_a - p_b|, p = t x_v1 + (1 - t)
  /// x_v2 the position of a copy (its largest value is Diagnostics::stitch_gap_max)
  std::vector<double> stitch_gap;
};
Fields fields(const DogProblem& problem, const Dofs& x);

}  // namespace sdog
