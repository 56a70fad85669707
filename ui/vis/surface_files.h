#pragma once
// The trimmed surface (geometry/surface/trimmed_surface.h) as files for other programs (Blender,
// MeshLab, ParaView), in sheet units:
// - OBJ (Wavefront, text): `v` positions, `vn` normals, `f a//a b//b c//c` triangles, through VTK's
//   vtkOBJWriter (full double precision);
// - PLY (binary little endian): per vertex float x, y, z, float nx, ny, nz and uchar red, green,
//   blue, per face a uchar count and int indices. Written here: VTK 9.1's vtkPLYWriter writes no
//   normals and does not report a file it could not open;
// - FOLD folded form (JSON): the surface with its creases' fold angles as reached, for Origami
//   Simulator and the FOLD tools (geometry/surface/folded_form.h).
// Sheet units are the pattern's (dog_mesh.h): x, y = mesh / scale + sheet_origin, z = mesh / scale.
// Normals are the surface's (a uniform scale and a shift keep them).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/dog_mesh.h"
#include "geometry/surface/mesh_arrays.h"
#include "geometry/surface/trimmed_surface.h"
#include "ui/vis/layers.h"

namespace sdog::vis {

enum class SurfaceFormat { kObj, kPly, kFold };
}  // namespace sdog::vis

namespace sdog {
/// "obj", "ply", "fold": the file extension, without the dot, and the name on the command line.
template <>
struct EnumNames<vis::SurfaceFormat> {
  static constexpr const char* noun = "format";
  static constexpr EnumName<vis::SurfaceFormat> rows[] = {{vis::SurfaceFormat::kObj, "obj"},
                                                          {vis::SurfaceFormat::kPly, "ply"},
                                                          {vis::SurfaceFormat::kFold, "fold"}};
};
}  // namespace sdog

namespace sdog::vis {
/// Parses "obj,ply" (comma separated, no duplicates, no empty names, at least one). Throws
/// UsageError, `context` followed by the bad name and the known formats.
std::vector<SurfaceFormat> parse_surface_formats(const std::string& text,
                                                 const std::string& context = "");
/// The format a path's extension names (.obj, .ply in any case), if any.
std::optional<SurfaceFormat> format_of_path(const std::string& path);
/// `path` itself when its extension names a format, else `path` + "." + the extension of
/// `fallback`.
std::string with_surface_extension(const std::string& path, SurfaceFormat fallback);

/// Positions X (mesh units, n x 3) of `mesh` in sheet units.
Eigen::MatrixX3d to_sheet_units(const DogMesh& mesh, const Eigen::MatrixX3d& X);

/// Writes `surface` (mesh units, a surface of `mesh`) as `format` in sheet units to `path`; a PLY
/// with the vertex colours of the colour layer `colour` (surface_colours.h) from the fine mesh's
/// arrays `mesh_arrays` (frame_arrays). Throws OutputError naming the path.
void write_surface_file(SurfaceFormat format, const TrimmedSurface& surface, const DogMesh& mesh,
                        Layer colour, const MeshArrays& mesh_arrays, const std::string& path);

}  // namespace sdog::vis
