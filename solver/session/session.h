#pragma once
// An interactive run (the studio's model, Qt-free): a DOG model, its problem, a solver mode and
// the fine positions, stepped one iteration at a time, with constraints the user adds, moves and
// removes, undo and redo of those edits, and mode switches that keep the state.
//
// The targets are those of a base scenario (corners, fold, none: the run configuration's) plus the
// user's constraints, which hold their targets from the start. Every edit rebuilds the mode on the
// current positions (switch_mode; the modes keep their own copy of the targets, and adding or
// removing a constraint changes the solver's sparsity pattern) and tells it the session's start
// state (switch_mode's origin), from which the standard mode settles. Undo and redo restore the
// user's constraints and crease assignments, not the positions: the sheet stays where the solver
// put it.
//
// The session solves its own copy of the model with the run configuration's crease settings
// (config().creases, crease_settings.h) applied. The user's assignment and angle edits become
// settings of that list, so a workspace (which keeps the configuration) keeps them.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "solver/run/run.h"
#include "solver/run/run_config.h"
#include "solver/run/run_setup.h"

namespace sdog {

/// The user's constraints: handles (a fine vertex held at a target) and dihedral angles at crease
/// points.
struct UserConstraints {
  struct Handle {
    int vertex;
    Eigen::Vector3d target;
  };
  struct Angle {
    int crease_point;
    double degrees;
  };
  std::vector<Handle> handles;
  std::vector<Angle> angles;
};

class Session {
 public:
  /// The configuration's scenario (make_scenario) from its start state, on a copy of `model` with
  /// the configuration's crease settings. Throws UsageError for an unusable mode (a coarse mode
  /// without the coarse mesh), InputError for a crease setting naming no crease.
  Session(const DogModel& model, const RunConfig& config, ModeKind mode);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  /// The model solved: the given one with the crease settings of config() applied.
  const DogModel& model() const { return model_; }
  const RunConfig& config() const { return config_; }
  ModeKind mode() const { return mode_kind_; }
  /// Fine positions.
  const Dofs& positions() const { return x_; }
  /// The coarse positions of a mode that steps a coarse mesh (coarse, twolevel), else nullptr.
  const Dofs* coarse_positions() const { return mode_->coarse_positions(); }
  /// Scenario time of the last iteration (0 before the first).
  double time() const { return iteration_ > 0 ? base_.time_of(iteration_) : 0.0; }
  /// The base scenario's targets no longer move: its time has reached 1, or it has none that move
  /// (none, flatten).
  bool scenario_done() const {
    return time() >= 1 || config_.scenario == ScenarioKind::kNone ||
           config_.scenario == ScenarioKind::kFlatten;
  }
  /// Iterations taken since the start or the last reset.
  int iteration() const { return iteration_; }
  /// Base scenario plus the user's constraints, as the solver sees them.
  const Scenario& scenario() const { return scenario_; }
  const DogProblem& problem() const { return *problem_; }
  const UserConstraints& constraints() const { return user_; }

  /// One iteration (targets at the base scenario's time of the next iteration). A failed iteration
  /// leaves the positions as they were and is reported in the returned report's step.
  IterationReport step();
  /// Back to the start state (iteration 0); the constraints stay.
  void reset();
  /// Continue with another mode from the current positions (Mode::start_from).
  void set_mode(ModeKind mode);
  /// Replaces the positions (a loaded workspace); throws InputError on a size mismatch.
  void set_positions(const Dofs& x, int iteration);

  /// Editing. Each is one undoable edit; indices are positions in constraints().handles / .angles.
  /// Throws InputError for a vertex or crease point that does not exist, or a crease point that is
  /// not between exactly two patches.
  int add_handle(int vertex);  ///< target: the vertex's current position
  /// Several vertices made handles at once (rubber-band selection), as one edit; returns the
  /// index of the first new handle.
  int add_handles(const std::vector<int>& vertices);
  /// A handle on `vertex` with the given target, as one edit: what dragging a target of the base
  /// scenario (a corner of the corners scenario) does first. A handle on a vertex replaces the base
  /// scenario's target for it. Returns its index.
  int add_handle_at(int vertex, const Eigen::Vector3d& target);
  /// `merge`: the move continues the last edit (a drag in progress) and is undone with it.
  void move_handle(int handle, const Eigen::Vector3d& target, bool merge = false);
  void remove_handle(int handle);
  /// On the flat sheet, also tilts the sheet towards the fold (fold_seed.h), which is otherwise a
  /// symmetric point the solver cannot leave.
  int add_angle(int crease_point, double degrees);
  void remove_angle(int angle);
  /// Replaces every user constraint at once (a loaded workspace), as one edit.
  void set_constraints(const UserConstraints& constraints);
  /// The assignment and/or fold angle (degrees, 0 to 180) of the creases `curves` (indices among
  /// the cleaned creases), as apply_crease_settings sets them: one undoable edit, added to
  /// config().creases. The base scenario and the problem are rebuilt; the positions stay (the
  /// fold scenario goes on from the current shape). Throws InputError for a crease that does not
  /// exist or an angle out of range.
  void set_creases(const std::vector<int>& curves, std::optional<Fold> fold,
                   std::optional<double> angle);
  /// Starts the fold scenario (config().scenario becomes fold) from the flat sheet tilted towards
  /// the assignments; the constraints and the undo history stay. Throws UsageError when the
  /// pattern has no fold sites at this resolution.
  void fold();
  /// The fold amount (0 to 100% of every crease's angle, config().fold_percent): the fold
  /// scenario's targets move there from the current shape, which folds or unfolds the sheet as the
  /// session steps; starts the fold scenario (fold()) when another one runs. Not an undoable edit
  /// (a view of the fold, like Origami Simulator's fold percent). Throws InputError out of range.
  void set_fold_percent(double percent);
  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  /// What undo() and redo() would undo or redo ("move handle 2", "assign 3 creases valley", ...;
  /// empty when there is nothing).
  std::string undo_name() const { return undo_.empty() ? std::string() : undo_.back().name; }
  std::string redo_name() const { return redo_.empty() ? std::string() : redo_.back().name; }
  bool undo();
  bool redo();

 private:
  // What an undo step restores.
  struct EditState {
    UserConstraints user;
    std::vector<CreaseSetting> creases;
    std::string name;  // of the edit that left this state
  };
  // Records the undo step (named `name`) and rebuilds.
  void edit(const UserConstraints& next, const std::string& name, bool merge = false);
  // Undo (from undo_ to redo_) or redo (the other way).
  bool travel(std::vector<EditState>& from, std::vector<EditState>& to);
  void rebuild();
  // model_'s creases from source_ with config_.creases applied; the problem and base scenario anew.
  void apply_creases();
  void check_vertex(int vertex) const;

  const DogModel& source_;
  DogModel model_;
  RunConfig config_;
  ModeKind mode_kind_;
  Scenario base_, scenario_;
  std::unique_ptr<DogProblem> problem_;
  std::unique_ptr<Mode> mode_;
  Dofs x_;
  /// The state the session started from (the start state, or the sheet tilted towards a fold);
  /// every mode is told it (switch_mode's origin).
  Dofs origin_;
  int iteration_ = 0;
  UserConstraints user_;
  std::vector<EditState> undo_, redo_;
};

}  // namespace sdog
