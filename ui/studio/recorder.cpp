#include "ui/studio/recorder.h"

#include <cstdio>
#include <filesystem>

#include "base/atomic_output.h"
#include "base/errors.h"
#include "ui/vis/frame_writer.h"
#include "ui/vis/surface_series.h"

namespace sdog::studio {
namespace fs = std::filesystem;

void Recorder::check(const RecordingOptions& options) {
  if (!options.png && !options.vtu && !options.surface)
    throw UsageError("nothing to record: choose pictures (PNG), meshes (.vtu) or surfaces (.vtp)");
  if (options.every < 1) throw UsageError("record every " + std::to_string(options.every) + " iterations: must be 1 or more");
}

Recorder::Recorder(const DogModel& model, std::string dir, const RecordingOptions& options)
    : model_(model), dir_(std::move(dir)), options_(options) {
  check(options);
  OutputSet folder(dir_);  // creates the folder, or says why it cannot be written
  if (fs::exists(fs::path(dir_) / "frames.csv"))
    throw OutputError(dir_ + " already holds a recording (frames.csv): choose another folder");
  folder.commit();  // keeps the folder
  table_ = "frame,iteration,time,files\n";
}

Recorder::~Recorder() = default;

bool Recorder::due(int iteration) const {
  if (frames_ == 0) return true;
  return iteration != last_iteration_ && iteration % options_.every == 0;
}

void Recorder::record(const vis::SceneState& state, int iteration, double time, const vis::PictureOptions& picture) {
  char stem[32];
  std::snprintf(stem, sizeof stem, "%04d", frames_);
  const std::string frame = std::string("frame_") + stem, surface = std::string("surface_") + stem;
  OutputSet out(dir_);
  std::string files;
  auto add = [&](const std::string& name) { files += (files.empty() ? "" : " ") + name; };
  vis::TimeSteps vtu_steps = vtu_steps_, surface_steps = surface_steps_;
  if (options_.png) {
    vis::render_picture(model_, state, picture, out.temporary(frame + ".png"));
    add(frame + ".png");
  }
  const MeshArrays arrays = options_.vtu || options_.surface ? vis::frame_arrays(model_, state.fields) : MeshArrays{};
  if (options_.vtu) {
    vis::write_frame_vtu(model_, state.fine, arrays, out.temporary(frame + ".vtu"));
    vtu_steps.emplace_back(iteration, frame + ".vtu");
    out.write_text("frames.pvd", vis::pvd_collection(vtu_steps));
    add(frame + ".vtu");
  }
  if (options_.surface) {
    if (!surface_) surface_ = std::make_unique<TrimmedSurface>(trimmed_surface(model_.fine, state.fine));
    place_trimmed_surface(*surface_, state.fine);
    vis::write_surface_vtp(*surface_, arrays, out.temporary(surface + ".vtp"));
    surface_steps.emplace_back(iteration, surface + ".vtp");
    out.write_text("surface.pvd", vis::pvd_collection(surface_steps));
    add(surface + ".vtp");
  }
  char row[96];
  std::snprintf(row, sizeof row, "%d,%d,%.6g,", frames_, iteration, time);
  const std::string table = table_ + row + files + "\n";
  out.write_text("frames.csv", table);
  std::uintmax_t before = 0;
  for (const char* rewritten : {"frames.csv", "frames.pvd", "surface.pvd"}) {
    std::error_code ec;
    const auto size = fs::file_size(fs::path(dir_) / rewritten, ec);
    if (!ec) before += size;
  }
  std::uintmax_t after = 0;
  for (const std::string& path : out.commit()) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (!ec) after += size;
  }
  bytes_ += after - before;
  table_ = table;
  vtu_steps_ = std::move(vtu_steps);
  surface_steps_ = std::move(surface_steps);
  last_iteration_ = iteration;
  ++frames_;
}

}  // namespace sdog::studio
