#pragma once
// The frames FrameWriter saves (sdog run --out, the studio's recordings), read back: the list of
// frames.pvd and a frame's fine positions, with the check that a frame belongs to the mesh it is
// drawn on (same vertex count, quads and rest positions).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/dog_mesh.h"

namespace sdog::vis {

/// One entry of frames.pvd.
struct FrameEntry {
  int iteration = 0;  ///< the time step
  std::string path;   ///< the frame file, relative names joined to the folder of frames.pvd
};

/// The frames a frames.pvd lists, in its order. Throws InputError naming the file when it is
/// missing, not XML or not a collection of frames with integer time steps.
std::vector<FrameEntry> read_frame_list(const std::string& pvd_path);

/// The frame of `iteration` (none: the last one) among `frames` listed by `pvd_path`. Throws
/// InputError naming the file and the iterations it has ("0 to 100 every 10, and 105").
FrameEntry find_frame(const std::vector<FrameEntry>& frames, std::optional<int> iteration,
                      const std::string& pvd_path);

/// Iterations in words: "0 to 100 every 10", "0 to 300 every 10, and 305" (a last one off the
/// stride), "0, 3, 7" (any other list; long ones shortened in the middle).
std::string describe_iterations(const std::vector<int>& iterations);

/// A frame file read back.
struct SavedFrame {
  Eigen::MatrixX3d positions;  ///< fine positions, one row per vertex
  Eigen::MatrixX4i quads;      ///< its cells (every one a quad)
  std::optional<Eigen::MatrixX3d>
      rest;  ///< its rest_position array (absent in frames of other writers)
};

/// Reads a frame (.vtu); throws InputError naming the file when it is missing, not a VTK
/// unstructured grid, or not a quad mesh with finite positions.
SavedFrame read_frame(const std::string& path);

/// Throws InputError "FRAME is not a frame of MODEL: ..." (MODEL such as "four_corner_arcs.svg at
/// 41x41") when the frame has another vertex count or other quads than `fine`, or rest positions
/// farther than 1e-9 sheet sizes from `fine`'s (another pattern or other mesh options).
void check_frame_of(const SavedFrame& frame, const DogMesh& fine, const std::string& frame_path,
                    const std::string& model_name);

}  // namespace sdog::vis
