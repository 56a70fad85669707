#include "ui/vis/surface_files.h"

#include <vtkOBJWriter.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "base/errors.h"
#include "geometry/surface/folded_form.h"
#include "ui/vis/surface_colours.h"
#include "ui/vis/vtk_meshes.h"

namespace sdog::vis {
namespace {

void write_obj(const TrimmedSurface& surface, const std::string& path) {
  take_vtk_error();  // installs the capture of VTK's messages, drops an old one
  auto writer = vtkSmartPointer<vtkOBJWriter>::New();
  writer->SetFileName(path.c_str());
  writer->SetInputData(triangle_surface(surface, {}));
  check_written(writer->Write() == 1 && writer->GetErrorCode() == 0, path, "the OBJ file");
}

// Little-endian bytes, whatever the machine's order.
void put_u32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}
void put_float(std::string& out, double v) {
  const auto f = static_cast<float>(v);
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  put_u32(out, bits);
}

void write_ply(const TrimmedSurface& surface, const std::vector<Rgb8>& colours,
               const std::string& path) {
  std::ostringstream header;
  header << "ply\nformat binary_little_endian 1.0\ncomment Scalable DOGs trimmed surface, sheet "
            "units\n"
         << "element vertex " << surface.vertex_count() << "\n"
         << "property float x\nproperty float y\nproperty float z\n"
         << "property float nx\nproperty float ny\nproperty float nz\n"
         << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
         << "element face " << surface.triangle_count() << "\n"
         << "property list uchar int vertex_indices\nend_header\n";
  std::string data = header.str();
  data.reserve(data.size() + 27 * static_cast<size_t>(surface.vertex_count()) +
               13 * static_cast<size_t>(surface.triangle_count()));
  for (int v = 0; v < surface.vertex_count(); ++v) {
    for (int k = 0; k < 3; ++k) put_float(data, surface.V(v, k));
    for (int k = 0; k < 3; ++k) put_float(data, surface.N(v, k));
    for (unsigned char c : colours[static_cast<size_t>(v)]) data.push_back(static_cast<char>(c));
  }
  for (int t = 0; t < surface.triangle_count(); ++t) {
    data.push_back(3);
    for (int k = 0; k < 3; ++k) put_u32(data, static_cast<std::uint32_t>(surface.T(t, k)));
  }
  std::ofstream out(path, std::ios::binary);
  out << data;
  out.close();
  if (!out) throw OutputError(path + ": cannot write the PLY file (" + std::strerror(errno) + ")");
}

}  // namespace

std::vector<SurfaceFormat> parse_surface_formats(const std::string& text,
                                                 const std::string& context) {
  return parse_enum_list<SurfaceFormat>(text, context);
}

std::optional<SurfaceFormat> format_of_path(const std::string& path) {
  const size_t dot = path.find_last_of("./");
  if (dot == std::string::npos || path[dot] != '.') return std::nullopt;
  std::string extension = path.substr(dot + 1);
  for (auto& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return find_enum<SurfaceFormat>(extension);
}

std::string with_surface_extension(const std::string& path, SurfaceFormat fallback) {
  return format_of_path(path) ? path : path + "." + enum_name(fallback);
}

Eigen::MatrixX3d to_sheet_units(const DogMesh& mesh, const Eigen::MatrixX3d& X) {
  Eigen::MatrixX3d sheet = X / mesh.scale;
  sheet.col(0).array() += mesh.sheet_origin.x();
  sheet.col(1).array() += mesh.sheet_origin.y();
  return sheet;
}

void write_surface_file(SurfaceFormat format, const TrimmedSurface& surface, const DogMesh& mesh,
                        Layer colour, const MeshArrays& mesh_arrays, const std::string& path) {
  TrimmedSurface sheet = surface;
  sheet.V = to_sheet_units(mesh, surface.V);
  if (format == SurfaceFormat::kObj) {
    write_obj(sheet, path);
  } else if (format == SurfaceFormat::kPly) {
    write_ply(sheet, surface_colours(colour, surface, mesh_arrays), path);
  } else {
    std::ofstream out(path);
    out << folded_form_fold(sheet, kWeldGridEdges / mesh.scale, path);
    out.close();
    if (!out)
      throw OutputError(path + ": cannot write the FOLD file (" + std::strerror(errno) + ")");
  }
}

}  // namespace sdog::vis
