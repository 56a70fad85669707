#pragma once
// The trimmed surface of a run's frames (frame_writer.h) and of its final state, for ParaView and
// for other programs:
// - surface_NNNN.vtp beside every frame_NNNN.vtu: the surface at the frame's positions (mesh
//   units) with point normals "Normals" and the frame's arrays carried over (trimmed_arrays: point
//   arrays interpolated, cell arrays per triangle from its quad), and surface.pvd listing them
//   (time = iteration);
// - with export formats (surface_files.h), surface_NNNN.obj / .ply of every frame and surface.obj /
//   .ply of the final state, in sheet units.
// The surface's topology is built once, from the rest state; each state only moves it. Files go
// into an OutputSet, so a failed run leaves none behind.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "base/atomic_output.h"
#include "geometry/mesh/dog_mesh.h"
#include "geometry/surface/mesh_arrays.h"
#include "geometry/surface/trimmed_surface.h"
#include "ui/vis/layers.h"
#include "ui/vis/pvd_collection.h"
#include "ui/vis/surface_files.h"

namespace sdog::vis {

struct SurfaceExport {
  std::vector<SurfaceFormat> formats;  ///< OBJ and PLY files to write besides the .vtp (none: none)
  Layer colour = Layer::kPatches;      ///< the colour layer of the PLY files' vertex colours
};

/// Writes the surface (placed at a state) as a .vtp file with normals and the state's fine mesh
/// arrays carried over (throws OutputError).
void write_surface_vtp(const TrimmedSurface& surface, const MeshArrays& mesh_arrays,
                       const std::string& path);

class SurfaceSeries {
 public:
  /// `mesh` (the fine mesh) and `out` must outlive the series.
  SurfaceSeries(const DogMesh& mesh, OutputSet& out, SurfaceExport exports);
  /// surface_NNNN.vtp (NNNN = iteration, at least 4 digits) and the export formats of the state
  /// at positions X (mesh units) with the fine mesh's arrays of that state (frame_arrays).
  void write_frame(int iteration, const Eigen::MatrixX3d& X, const MeshArrays& mesh_arrays);
  /// surface.obj / surface.ply of the final state (nothing without export formats).
  void write_final(const Eigen::MatrixX3d& X, const MeshArrays& mesh_arrays);
  /// Writes surface.pvd listing the frames written so far (nothing when there are none).
  void finish();
  int frame_count() const { return static_cast<int>(frames_.size()); }
  const SurfaceExport& exports() const { return exports_; }

 private:
  void write_exports(const std::string& stem, const MeshArrays& mesh_arrays);
  const DogMesh& mesh_;
  OutputSet& out_;
  SurfaceExport exports_;
  TrimmedSurface surface_;
  TimeSteps frames_;  // (iteration, .vtp file name)
};

}  // namespace sdog::vis
