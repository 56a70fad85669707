#pragma once
// What a scene shows of a model at one moment: positions, the solver's per-element fields and the
// constraints. A plain value: a solver thread makes one after an iteration and hands it to the
// scene (Scene::update), which never reads the solver's objects.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "solver/problem/diagnostics.h"
#include "solver/problem/scenario.h"

namespace sdog::vis {

/// The constraints the handles layer draws.
struct ConstraintView {
  struct Handle {
    int vertex;              ///< fine vertex
    Eigen::Vector3d target;  ///< where the solver pulls it (mesh units)
  };
  struct AngleSite {
    int point;              ///< crease point
    double target_degrees;  ///< dihedral angle asked for (0 flat)
  };
  std::vector<Handle> handles;
  std::vector<AngleSite> angle_sites;
};

/// The scenario's constraints with their targets at scenario time t in [0, 1].
ConstraintView constraint_view(const Scenario& scenario, double t);

struct SceneState {
  Eigen::MatrixX3d fine;    ///< fine positions (vertex_count x 3)
  Eigen::MatrixX3d coarse;  ///< coarse positions; no rows: the coarse rest state
  Fields fields;  ///< of `fine` (diagnostics.h): dog_residual, bending, edge_strain, stitch_gap
  ConstraintView constraints;
  /// Assignment of each crease curve (the cleaned creases, in order) as the run folds them;
  /// empty: the model's own.
  std::vector<Fold> crease_folds;
};

/// The state of a run: fine dofs `x` measured on `problem` (its current targets), the coarse
/// dofs of a mode with a coarse mesh (Mode::coarse_positions(), or nullptr) and the scenario's
/// constraints at time t (nullptr: none).
SceneState scene_state(const DogProblem& problem, const Dofs& x, const Dofs* coarse_x = nullptr,
                       const Scenario* scenario = nullptr, double t = 1);

/// The flat rest state of the model (every residual 0) with the scenario's constraints at their
/// final targets (t = 1; nullptr: none), which shows what a run would ask for.
SceneState rest_scene_state(const DogModel& model, const Scenario* scenario = nullptr);

/// Floor of the log10 DOG residual: residuals below it (and vertices without DOG rows) are shown
/// at log10(kResidualFloor).
inline constexpr double kResidualFloor = 1e-10;

/// log10(max(r, kResidualFloor)) per value: the values the dog-residual layer colours by.
std::vector<double> log10_residuals(const std::vector<double>& residuals);

}  // namespace sdog::vis
