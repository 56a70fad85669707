#include "ui/vis/surface_series.h"

#include <cstdio>

#include "ui/vis/vtk_meshes.h"

namespace sdog::vis {

SurfaceSeries::SurfaceSeries(const DogMesh& mesh, OutputSet& out, SurfaceExport exports)
    : mesh_(mesh),
      out_(out),
      exports_(std::move(exports)),
      surface_(trimmed_surface(mesh, mesh.V)) {}

void write_surface_vtp(const TrimmedSurface& surface, const MeshArrays& mesh_arrays,
                       const std::string& path) {
  write_vtp(triangle_surface(surface, trimmed_arrays(surface, mesh_arrays)), path);
}

void SurfaceSeries::write_frame(int iteration, const Eigen::MatrixX3d& X,
                                const MeshArrays& mesh_arrays) {
  char stem[32];
  std::snprintf(stem, sizeof stem, "surface_%04d", iteration);
  place_trimmed_surface(surface_, X);
  const std::string name = std::string(stem) + ".vtp";
  write_surface_vtp(surface_, mesh_arrays, out_.temporary(name));
  frames_.emplace_back(iteration, name);
  write_exports(stem, mesh_arrays);
}

void SurfaceSeries::write_final(const Eigen::MatrixX3d& X, const MeshArrays& mesh_arrays) {
  if (exports_.formats.empty()) return;
  place_trimmed_surface(surface_, X);
  write_exports("surface", mesh_arrays);
}

void SurfaceSeries::write_exports(const std::string& stem, const MeshArrays& mesh_arrays) {
  for (SurfaceFormat format : exports_.formats)
    write_surface_file(format, surface_, mesh_, exports_.colour, mesh_arrays,
                       out_.temporary(stem + "." + enum_name(format)));
}

void SurfaceSeries::finish() {
  if (!frames_.empty()) out_.write_text("surface.pvd", pvd_collection(frames_));
}

}  // namespace sdog::vis
