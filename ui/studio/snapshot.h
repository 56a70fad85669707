#pragma once
// What the solver thread hands to the window: plain values (no pointers into the session), sent
// through queued Qt signals.
#include <QMetaType>
#include <optional>
#include <string>
#include <vector>

#include "solver/run/run.h"
#include "solver/session/session.h"
#include "ui/vis/scene_state.h"

namespace sdog::studio {

/// The session's state after a command (an iteration, an edit, a reset, ...).
struct Snapshot {
  vis::SceneState state;
  int iteration = 0;
  std::string mode;
  UserConstraints constraints;
  /// The fold angle of each crease curve as the session folds it (degrees; none: the scenario's);
  /// the assignments are state.crease_folds.
  std::vector<std::optional<double>> crease_angles;
  /// The session's run configuration: its crease settings (the user's edits included) and
  /// scenario.
  std::vector<CreaseSetting> crease_settings;
  ScenarioKind scenario = ScenarioKind::kCorners;
  bool can_undo = false, can_redo = false;
  std::string undo_name, redo_name;  ///< what Undo and Redo would undo or redo (Session::undo_name)
  double time = 0;                   ///< scenario time of the iteration (Session::time)
  bool scenario_done = false;        ///< the base scenario's targets no longer move
};

}  // namespace sdog::studio

Q_DECLARE_METATYPE(sdog::studio::Snapshot)
Q_DECLARE_METATYPE(sdog::IterationReport)
