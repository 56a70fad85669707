#pragma once
// Named per-element arrays: one definition feeds the VTK export, the renderer's colouring and
// (later) the solver diagnostics. A point array has one value per vertex, a cell array one per
// quad.
#include <string>
#include <vector>

namespace sdog {

struct NamedArray {
  std::string name;
  std::vector<double> values;
  bool integral = false;  ///< written as an integer array
};

struct MeshArrays {
  std::vector<NamedArray> point, cell;
  const NamedArray* find_point(const std::string& name) const;
};

struct DogMesh;
struct DogModel;

/// The cell array "patch": the patch of each quad of the mesh.
NamedArray quad_patch(const DogMesh& mesh);

/// Fine mesh arrays: vertex_type (link 0, I 1, X 2), patch, partner (coarse twin or -1),
/// vertex_class (star 0, bnd3 1, bnd2 2, bnd4 3); cell array patch.
MeshArrays fine_mesh_arrays(const DogModel& model);
/// Coarse mesh arrays: vertex_type (link 0, coarse-only 3), patch, partner (fine twin or -1),
/// vertex_class; cell array patch.
MeshArrays coarse_mesh_arrays(const DogModel& model);

}  // namespace sdog
