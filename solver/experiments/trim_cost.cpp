#include "solver/experiments/trim_cost.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/stopwatch.h"
#include "geometry/surface/trimmed_surface.h"

namespace sdog {

TrimCost measure_trim_cost(const DogMesh& mesh, int repeats) {
  TrimCost cost;
  auto t0 = Clock::now();
  TrimmedSurface surface = trimmed_surface(mesh, mesh.V);
  cost.build_ms = ms_since(t0);
  cost.triangles = surface.triangle_count();
  // A frame's arrays: three per vertex, two per quad.
  MeshArrays arrays;
  for (const char* name : {"dog_residual", "bending", "position_residual"})
    arrays.point.push_back({name, std::vector<double>(mesh.vertex_count(), 1e-6), false});
  for (const char* name : {"patch", "edge_strain"})
    arrays.cell.push_back({name, std::vector<double>(mesh.quad_count(), 0.0), false});
  std::vector<double> times;
  MeshArrays carried;
  Eigen::MatrixX3d X = mesh.V;
  for (int r = 0; r < std::max(repeats, 1); ++r) {
    X.col(2) =
        (0.01 * (r + 1)) * mesh.V.col(0).array().square();  // a different bent state each time
    t0 = Clock::now();
    place_trimmed_surface(surface, X);
    carried = trimmed_arrays(surface, arrays);
    times.push_back(ms_since(t0));
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  cost.state_ms = times[times.size() / 2];
  return cost;
}

}  // namespace sdog
