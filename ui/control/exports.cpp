#include "ui/control/exports.h"

#include <filesystem>

#include "base/atomic_output.h"
#include "geometry/surface/trimmed_surface.h"
#include "ui/vis/frame_writer.h"
#include "ui/vis/surface_files.h"

namespace sdog::control {

std::string with_extension(const std::string& path, const std::string& extension) {
  return std::filesystem::path(path).extension().empty() ? path + "." + extension : path;
}

void write_whole_file(const std::string& path,
                      const std::function<void(const std::string&)>& write) {
  const std::filesystem::path target(path);
  OutputSet out(target.has_parent_path() ? target.parent_path().string() : ".");
  write(out.temporary(target.filename().string()));
  out.commit();
}

std::string export_picture(const DogModel& model, const vis::SceneState& state,
                           const vis::PictureOptions& options, const std::string& path) {
  const std::string file = with_extension(path, "png");
  write_whole_file(
      file, [&](const std::string& tmp) { vis::render_picture(model, state, options, tmp); });
  return file;
}

std::string export_surface(const DogModel& model, const vis::SceneState& state, vis::Layer colour,
                           const std::string& path) {
  const std::string file = vis::with_surface_extension(path, vis::SurfaceFormat::kObj);
  const vis::SurfaceFormat format = vis::format_of_path(file).value_or(vis::SurfaceFormat::kObj);
  const TrimmedSurface surface = trimmed_surface(model.fine, state.fine);
  const MeshArrays arrays = vis::frame_arrays(model, state.fields);
  write_whole_file(file, [&](const std::string& tmp) {
    vis::write_surface_file(format, surface, model.fine, colour, arrays, tmp);
  });
  return file;
}

}  // namespace sdog::control
