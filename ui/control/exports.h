#pragma once
// What File > Export writes: a picture of the current state and its trimmed surface (OBJ, PLY),
// each whole or not at all (written under a temporary name, then renamed).
#include <functional>
#include <string>

#include "geometry/mesh/dog_model.h"
#include "ui/vis/layers.h"
#include "ui/vis/picture.h"
#include "ui/vis/scene_state.h"

namespace sdog::control {

/// `path` with `.extension` appended when its file name has no extension (what the save dialogs
/// do with a name typed without one).
std::string with_extension(const std::string& path, const std::string& extension);

/// Calls write(temporary path) and gives the file `path` its name only when that succeeded.
/// Throws OutputError when the folder cannot be written.
void write_whole_file(const std::string& path,
                      const std::function<void(const std::string&)>& write);

/// The picture of `state` drawn with `options` (vis/picture.h) written to `path` (.png appended to
/// a name without an extension); returns the file written. Throws OutputError.
std::string export_picture(const DogModel& model, const vis::SceneState& state,
                           const vis::PictureOptions& options, const std::string& path);

/// The trimmed surface of `state` in sheet units (vis/surface_files.h), OBJ or PLY as the path's
/// extension says (.obj appended when it names neither), a PLY coloured by `colour`; returns the
/// file written. Throws OutputError.
std::string export_surface(const DogModel& model, const vis::SceneState& state, vis::Layer colour,
                           const std::string& path);

}  // namespace sdog::control
