#pragma once
// Solver frames for ParaView: frame_NNNN.vtu (the fine mesh in its current state) every K
// iterations, plus frame_0000 (the flat start) and the last iteration, tied together by
// frames.pvd (time = iteration). Point arrays: the fine mesh arrays (vertex_type, patch, partner,
// vertex_class), dog_residual, bending, position_residual and rest_position (the flat rest state,
// 3-vectors: it ties the frame to its model, saved_frames.h); cell arrays patch and edge_strain.
// Files go into an OutputSet, so a failed run leaves none behind. With a SurfaceSeries
// (surface_series.h), every frame's trimmed surface is written too.
#include <string>
#include <vector>

#include "base/atomic_output.h"
#include "geometry/mesh/dog_model.h"
#include "geometry/surface/mesh_arrays.h"
#include "solver/problem/diagnostics.h"
#include "solver/run/run.h"
#include "ui/vis/surface_series.h"

namespace sdog::vis {

/// The fine mesh at state x with the model's and the solver's arrays.
MeshArrays frame_arrays(const DogModel& model, const DogProblem& problem, const Dofs& x);
/// The same from the fields of a state (diagnostics.h).
MeshArrays frame_arrays(const DogModel& model, Fields fields);

/// Writes the fine mesh at positions X (mesh units) with `arrays` and rest_position as a .vtu
/// file: one frame (throws OutputError).
void write_frame_vtu(const DogModel& model, const Eigen::MatrixX3d& X, const MeshArrays& arrays,
                     const std::string& path);

class FrameWriter : public RunObserver {
 public:
  /// `every` >= 1; `last_iteration` is the run's final iteration (always written).
  FrameWriter(const DogModel& model, const DogProblem& problem, OutputSet& out, int every,
              int last_iteration);
  /// Writes frame_0000 of the start state.
  void write_start(const Dofs& x);
  /// Writes the trimmed surface of every frame from now on into `surfaces` (which must outlive the
  /// writer).
  void add_surfaces(SurfaceSeries& surfaces) { surfaces_ = &surfaces; }
  void on_iteration(const IterationReport& report, const Dofs& x) override;
  /// Writes frames.pvd listing the frames written so far.
  void finish();
  int frame_count() const { return static_cast<int>(frames_.size()); }

 private:
  void write(int iteration, const Dofs& x);
  const DogModel& model_;
  const DogProblem& problem_;
  OutputSet& out_;
  int every_, last_;
  TimeSteps frames_;  // (iteration, file name)
  SurfaceSeries* surfaces_ = nullptr;
};

}  // namespace sdog::vis
