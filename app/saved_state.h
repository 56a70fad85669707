#pragma once
// A state saved by a run, to draw it again (sdog render and sdog-studio with --frame FILE.vtu, or
// --run DIR [--iteration N] from DIR/frames.pvd): the frame, the run's record beside it (run.json)
// and the options of the model it belongs to: the record's, except those the command line gives
// (the frame must then fit them).
#include <functional>
#include <optional>
#include <string>

#include "app/cli_common.h"
#include "app/saved_run.h"
#include "geometry/mesh/dog_model.h"
#include "solver/session/workspace.h"
#include "ui/vis/saved_frames.h"
#include "ui/vis/scene_state.h"

namespace sdog::cli {

struct SavedStateRequest {
  std::string frame;             ///< --frame FILE.vtu
  std::string run;               ///< --run DIR
  std::optional<int> iteration;  ///< --iteration N with --run (none: the last frame)
  PatternOptions command_line;   ///< PATTERN, --res, ... as parsed
  /// Whether an option ("PATTERN", "--res", "--flatness", "--merge-tol", "--snap-tol",
  /// "--fine-only") is on the command line.
  std::function<bool(const std::string&)> given;
};

struct SavedState {
  std::string frame;  ///< the frame file
  std::optional<int>
      iteration;                ///< listed in frames.pvd beside it, or from its name frame_NNNN.vtu
  std::optional<SavedRun> run;  ///< the run.json beside the frame
  PatternOptions pattern;       ///< the model's options
  std::string model_source;     ///< "as DIR/run.json records it" or "as given on the command line"
  vis::SavedFrame data;
};

/// Finds and reads the frame and the record beside it. Throws InputError naming the file: a
/// missing or unreadable frame, run folder or frames.pvd, an iteration that was not saved (saying
/// which were), a bad run.json, and, when the command line gives no PATTERN, no run.json or a
/// pattern file that is no longer where the run found it.
SavedState load_saved_state(const SavedStateRequest& request);

/// The model of the state (build_model, then the run's crease settings) once the frame is
/// checked to be one of its fine mesh (InputError naming the frame and the model otherwise).
DogModel saved_state_model(const SavedState& state);

/// The run configuration of the state: the record's; without one the defaults with `scenario`.
RunConfig saved_state_config(const SavedState& state, ScenarioKind scenario);

/// The state as a studio workspace on `model` (saved_state_model): pattern, resolution, iteration
/// (0 when unknown), configuration, positions, and the mode: `mode` when given, else the run's at
/// the frame's iteration (without a record: standard).
Workspace saved_workspace(const SavedState& state, const DogModel& model,
                          const std::optional<std::string>& mode);

/// What the run's pictures showed at the frame: its positions, the fields measured on the model
/// with the configuration's weights (as the run and its frames measure them) and, with
/// `constraints`, the configuration's scenario at the frame's iteration (at its end without a
/// record or a known iteration). The coarse mesh is not saved: it is drawn at rest.
vis::SceneState saved_scene_state(const SavedState& state, const DogModel& model,
                                  const RunConfig& config, bool constraints);

}  // namespace sdog::cli
