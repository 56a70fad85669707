#include "solver/session/workspace.h"

#include <filesystem>

#include "base/atomic_output.h"
#include "base/errors.h"
#include "base/json_field.h"
#include "solver/config/run_config_json.h"

namespace sdog {
namespace {

using nlohmann::json;
constexpr const char* kFormat = "sdog-workspace";
constexpr int kVersion = 1;

}  // namespace

Workspace workspace_of(const Session& session, const std::string& pattern,
                       const std::string& resolution, const nlohmann::json& camera) {
  Workspace w;
  w.pattern = pattern;
  w.resolution = resolution;
  w.mode = enum_name(session.mode());
  w.iteration = session.iteration();
  w.config = session.config();
  w.constraints = session.constraints();
  w.camera = camera;
  w.positions = session.positions();
  return w;
}

json to_json(const Workspace& w) {
  const json config = to_json(w.config);
  json handles = json::array(), angles = json::array(), positions = json::array();
  for (const auto& h : w.constraints.handles)
    handles.push_back(
        {{"vertex", h.vertex}, {"target", {h.target.x(), h.target.y(), h.target.z()}}});
  for (const auto& a : w.constraints.angles)
    angles.push_back({{"crease_point", a.crease_point}, {"degrees", a.degrees}});
  for (Eigen::Index v = 0; v < w.positions.size() / 3; ++v)
    positions.push_back({w.positions[3 * v], w.positions[3 * v + 1], w.positions[3 * v + 2]});
  return {{"format", kFormat},          {"version", kVersion},   {"pattern", w.pattern},
          {"resolution", w.resolution}, {"mode", w.mode},        {"iteration", w.iteration},
          {"config", config},           {"handles", handles},    {"angles", angles},
          {"camera", w.camera},         {"positions", positions}};
}

Workspace workspace_from_json(const json& j, const std::string& source) {
  const Field root(j, "$", source);
  if (!j.is_object()) root.fail("expected a JSON object");
  if (!root.has("format")) root.fail("missing \"format\": not a workspace file");
  if (j["format"] != kFormat)
    root["format"].fail(std::string("not a workspace (expected \"") + kFormat + "\")");
  if (!root.has("version") || j["version"] != kVersion)
    root.fail("unsupported or missing \"version\" (this program reads version " +
              std::to_string(kVersion) + ")");
  root.expect_object({"format", "version", "pattern", "resolution", "mode", "iteration", "config",
                      "handles", "angles", "camera", "positions"});
  for (const char* key : {"pattern", "resolution", "mode"})
    if (!root.has(key)) root.fail(std::string("missing \"") + key + "\"");
  Workspace w;
  w.pattern = root["pattern"].text();
  w.resolution = root["resolution"].text();
  w.mode = root["mode"].text();
  if (root.has("iteration")) w.iteration = root["iteration"].integer(0);
  if (root.has("config")) apply_run_config(j["config"], source + " ($.config)", w.config);
  if (root.has("handles")) {
    const Field list = root["handles"];
    for (size_t i = 0; i < list.array_size(); ++i) {
      const Field h = list[i];
      h.expect_object({"vertex", "target"});
      if (!h.has("vertex") || !h.has("target")) h.fail("give \"vertex\" and \"target\"");
      w.constraints.handles.push_back({h["vertex"].integer(0), h["target"].vector<3>()});
    }
  }
  if (root.has("angles")) {
    const Field list = root["angles"];
    for (size_t i = 0; i < list.array_size(); ++i) {
      const Field a = list[i];
      a.expect_object({"crease_point", "degrees"});
      if (!a.has("crease_point") || !a.has("degrees"))
        a.fail("give \"crease_point\" and \"degrees\"");
      const double degrees = a["degrees"].number();
      if (!(std::abs(degrees) <= 180)) a["degrees"].fail("expected degrees in [-180, 180]");
      w.constraints.angles.push_back({a["crease_point"].integer(0), degrees});
    }
  }
  if (root.has("camera")) w.camera = j["camera"];
  if (root.has("positions")) {
    const Field list = root["positions"];
    w.positions.resize(3 * static_cast<Eigen::Index>(list.array_size()));
    for (size_t v = 0; v < list.array_size(); ++v)
      w.positions.segment<3>(3 * v) = list[v].vector<3>();
  }
  return w;
}

void save_workspace(const Workspace& w, const std::string& path) {
  const std::filesystem::path p(path);
  OutputSet out(p.has_parent_path() ? p.parent_path().string() : std::string("."));
  out.write_text(p.filename().string(), to_json(w).dump(1) + "\n");
  out.commit();
}

Workspace load_workspace(const std::string& path) {
  Workspace w = workspace_from_json(read_json_file(path, "workspace file"), path);
  const std::filesystem::path pattern(w.pattern);
  if (pattern.is_relative())
    w.pattern = (std::filesystem::path(path).parent_path() / pattern).lexically_normal().string();
  return w;
}

}  // namespace sdog
