#include "ui/control/recorder.h"

#include <cstdio>
#include <filesystem>

#include "base/atomic_output.h"
#include "base/errors.h"
#include "ui/vis/frame_writer.h"
#include "ui/vis/surface_series.h"

namespace sdog::control {
namespace fs = std::filesystem;

void Recorder::check(const RecordingOptions& options) {
  if (!options.png && !options.vtu && !options.surface)
    throw UsageError("nothing to record: choose pictures (PNG), meshes (.vtu) or surfaces (.vtp)");
  if (options.every < 1)
    throw UsageError("record every " + std::to_string(options.every) +
                     " iterations: must be 1 or more");
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

void Recorder::record(const vis::SceneState& state, int iteration, double time,
                      const vis::PictureOptions& picture) {
  char stem[32];
  std::snprintf(stem, sizeof stem, "%04d", frames_);
  const std::string frame = std::string("frame_") + stem, surface = std::string("surface_") + stem;
  OutputSet out(dir_);
  std::vector<std::string> names;  // this frame's files
  std::uintmax_t index_bytes = 0;  // frames.csv and the .pvd files, rewritten whole every frame
  auto write_index = [&](const std::string& name, const std::string& text) {
    out.write_text(name, text);
    index_bytes += text.size();
  };
  vis::TimeSteps vtu_steps = vtu_steps_, surface_steps = surface_steps_;
  if (options_.png) {
    names.push_back(frame + ".png");
    vis::render_picture(model_, state, picture, out.temporary(names.back()));
  }
  const MeshArrays arrays =
      options_.vtu || options_.surface ? vis::frame_arrays(model_, state.fields) : MeshArrays{};
  if (options_.vtu) {
    names.push_back(frame + ".vtu");
    vis::write_frame_vtu(model_, state.fine, arrays, out.temporary(names.back()));
    vtu_steps.emplace_back(iteration, names.back());
    write_index("frames.pvd", vis::pvd_collection(vtu_steps));
  }
  if (options_.surface) {
    if (!surface_)
      surface_ = std::make_unique<TrimmedSurface>(trimmed_surface(model_.fine, state.fine));
    place_trimmed_surface(*surface_, state.fine);
    names.push_back(surface + ".vtp");
    vis::write_surface_vtp(*surface_, arrays, out.temporary(names.back()));
    surface_steps.emplace_back(iteration, names.back());
    write_index("surface.pvd", vis::pvd_collection(surface_steps));
  }
  char row[64];
  std::snprintf(row, sizeof row, "%d,%d,%.6g,", frames_, iteration, time);
  std::string table = table_ + row;
  for (size_t k = 0; k < names.size(); ++k) table += (k ? " " : "") + names[k];
  table += "\n";
  write_index("frames.csv", table);
  out.commit();
  for (const std::string& name : names) {
    std::error_code ec;
    const auto size = fs::file_size(fs::path(dir_) / name, ec);
    if (!ec) frame_bytes_ += size;
  }
  index_bytes_ = index_bytes;
  table_ = std::move(table);
  vtu_steps_ = std::move(vtu_steps);
  surface_steps_ = std::move(surface_steps);
  last_iteration_ = iteration;
  ++frames_;
}

namespace {
std::string megabytes(std::uintmax_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return text;
}
}  // namespace

std::string recording_indicator(const Recorder& recorder) {
  return "\u25CF REC " + std::to_string(recorder.frame_count()) + " frames, " +
         megabytes(recorder.bytes());
}

std::string recording_summary(const Recorder& recorder, const std::string& dir) {
  return "recording stopped: " + std::to_string(recorder.frame_count()) + " frames (" +
         megabytes(recorder.bytes()) + ") in " + dir + " (frames.csv lists their iterations)";
}

}  // namespace sdog::control
