#pragma once
// Scenarios: what the user asks of the sheet over time. Targets move linearly with
// t = iteration / iterations (clamped to 1; the run then holds them for `hold` iterations).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "solver/problem/dog_problem.h"

namespace sdog {

/// Soft position constraint on a vertex, target moving from `start` to `end` (mesh units).
struct PositionConstraint {
  int vertex;
  Eigen::Vector3d start, end;
};

/// Signed dihedral angle at a fold site (its crease point), from start to end (degrees; 0 = flat,
/// positive valley, negative mountain; dihedral_angles.h).
struct AngleConstraint {
  int point;
  double start_degrees = 0, end_degrees = 0;
};

struct Scenario {
  std::string name;
  int iterations = 250;  ///< iterations over which targets move
  int hold = 50;         ///< iterations with the final targets
  std::vector<PositionConstraint> positions;
  std::vector<AngleConstraint> angles;
  /// Fold direction per crease curve for the start state (+1 valley, -1 mountain, 0 none); see
  /// fold_seed.h.
  std::vector<double> curve_signs;
  /// The start state, if not the flat mesh (flatten_scenario.h); empty: start from the flat mesh.
  Dofs initial;
  /// False when the scenario unfolds the creases: install() sets the fold-bias weight to 0 and the
  /// standard mode's folding mode (fold check and retries) is off.
  bool keeps_folds = true;

  /// Creates the problem's position and angle blocks (once; it fixes the sparsity pattern), and an
  /// angle block with target zero at every seam site the scenario leaves free, fold sites and
  /// seam_vertex_sites (seams stay smooth in every scenario; crease_pattern.h); zeroes the
  /// fold-bias weight unless keeps_folds.
  void install(DogProblem& problem) const;
  /// Sets the targets for time t in [0, 1].
  void apply(DogProblem& problem, double t) const;
  /// t before iteration `k` (1-based): min(1, k / iterations).
  double time_of(int iteration) const;
  /// The state a run starts from: `initial` if given, else the flat mesh tilted towards
  /// curve_signs (fold_seed.h).
  Dofs start(const DogMesh& mesh) const;
};

/// The thesis protocol: vertex a (the bottom-left grid corner) held, vertex c (the top-right grid
/// corner) moved from p_c to (0.6 x_c, 0.5 (y_c + y_a), 0.4 (y_c + y_a)) in 250 iterations, then
/// held for 50. (Mesh units, origin at the sheet's bottom-left corner: the reference's frame up to
/// a mirror in z, which leaves every objective value unchanged.)
Scenario corners_scenario(const DogMesh& mesh, int iterations = 250, int hold = 50);

/// Every fold site (a crease point where a crease crosses the inside of a grid edge between two
/// patches) folds from flat towards its crease's target (crease_fold_target, faded by fold_fades
/// towards an end inside the sheet), curved folding without dragging. The angle targets are signed,
/// so each crease folds the way its target says; the start state is tilted towards those directions
/// too (fold_seed.h). `percent`: the fold amount, the share of each target the sites end at (100:
/// the whole angle).
Scenario fold_scenario(const DogMesh& mesh, double degrees, int iterations = 250, int hold = 50,
                       double percent = 100);

/// The share of a crease's length over which the fold scenario fades its fold to flat towards an
/// end inside the sheet (where a seam continues it, crease_pattern.h): paper cannot keep a fold up
/// to a point inside it.
constexpr double kFadeShare = 0.25;
/// How the fold scenario fades a crease curve's target towards its ends inside the sheet.
struct FoldFade {
  std::vector<Eigen::Vector2d> inner_ends;  ///< flat positions of the ends where a seam starts
  double length = 0;                        ///< the crease's flat length
  /// The share of the crease's target asked at flat point p: the distance to the nearest inner
  /// end over kFadeShare of the length, at most 1 (1 for creases without such an end).
  double at(const Eigen::Vector2d& p) const;
};
/// One per stitching curve (slits, seams and closed curves have no inner ends).
std::vector<FoldFade> fold_fades(const DogMesh& mesh);

/// The signed fold angle (degrees; positive valley, negative mountain) the fold scenario asks of a
/// crease curve: 0 for a crease assigned flat; else the drawing's angle for it, or |degrees|,
/// towards its assignment; a crease without assignment folds the way `degrees`'s sign says
/// (0 counts as positive).
double crease_fold_target(const DogMesh& mesh, size_t curve, double degrees);

/// The fold site of crease point `point` among `sites`, or nullptr.
const FoldSite* find_fold_site(const std::vector<FoldSite>& sites, int point);

}  // namespace sdog
