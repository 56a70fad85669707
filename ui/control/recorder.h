#pragma once
// The studio's recording (File > Record frames): chosen states written into a folder as they are
// shown, numbered consecutively from frame_0000, each file under a temporary name first and then
// renamed, so that the folder holds only whole files and grows while the recording runs.
//
// Per recorded state, as chosen: frame_NNNN.png (the view as the studio draws it), frame_NNNN.vtu
// (the fine mesh with its arrays, as sdog run writes frames) and surface_NNNN.vtp (the trimmed
// surface). frames.csv lists every frame with its iteration and scenario time; frames.pvd and
// surface.pvd (time = iteration) are rewritten after every frame, so ParaView can open the series
// at any moment.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "geometry/surface/trimmed_surface.h"
#include "ui/vis/picture.h"
#include "ui/vis/pvd_collection.h"
#include "ui/vis/scene_state.h"

namespace sdog::control {

struct RecordingOptions {
  bool png = true;       ///< frame_NNNN.png
  bool vtu = false;      ///< frame_NNNN.vtu
  bool surface = false;  ///< surface_NNNN.vtp
  int every = 1;         ///< record the iterations that are multiples of this (and the start)
};

class Recorder {
 public:
  /// Records into `dir` (created if needed). Throws UsageError when nothing is chosen or `every` is
  /// below 1, OutputError when the folder cannot be written or already holds a recording
  /// (frames.csv).
  Recorder(const DogModel& model, std::string dir, const RecordingOptions& options);
  ~Recorder();

  /// Whether the state of `iteration` is to be recorded: a multiple of `every` not recorded yet
  /// (the first state is always recorded).
  bool due(int iteration) const;
  /// Writes the state's files as the next frame; `picture` says how the PNG is drawn. Throws
  /// OutputError (the frame's files are then not there).
  void record(const vis::SceneState& state, int iteration, double time,
              const vis::PictureOptions& picture);

  int frame_count() const { return frames_; }
  /// Bytes on disk of the recording's files.
  std::uintmax_t bytes() const { return frame_bytes_ + index_bytes_; }
  const std::string& dir() const { return dir_; }
  const RecordingOptions& options() const { return options_; }
  /// Checks the options (UsageError naming the problem).
  static void check(const RecordingOptions& options);

 private:
  const DogModel& model_;
  std::string dir_;
  RecordingOptions options_;
  std::unique_ptr<TrimmedSurface> surface_;  // topology built with the first surface written
  int frames_ = 0;
  int last_iteration_ = -1;
  std::uintmax_t frame_bytes_ = 0;  // the frames' files
  std::uintmax_t index_bytes_ = 0;  // frames.csv and the .pvd files as last written
  std::string table_;               // frames.csv
  vis::TimeSteps vtu_steps_, surface_steps_;
};

/// The status bar's indicator while recording: "● REC 12 frames, 3.4 MB".
std::string recording_indicator(const Recorder& recorder);
/// What a stopped recording says: how many frames, how big, and where (`dir` as shown).
std::string recording_summary(const Recorder& recorder, const std::string& dir);

}  // namespace sdog::control
