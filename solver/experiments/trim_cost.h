#pragma once
// What the trimmed surface (geometry/surface/trimmed_surface.h) costs a run that draws or writes
// it: its topology, built once per mesh, and each new state (positions, normals and the
// carried-over arrays of a frame), for `sdog bench --trim`.
#include "geometry/mesh/dog_mesh.h"

namespace sdog {

struct TrimCost {
  int triangles = 0;
  double build_ms = 0;  ///< the topology, once per mesh
  double state_ms =
      0;  ///< median per state: positions and normals, three point arrays and two cell arrays
};

/// Times the trimmed surface of `mesh` (the median over `repeats` states of a moved sheet).
TrimCost measure_trim_cost(const DogMesh& mesh, int repeats);

}  // namespace sdog
