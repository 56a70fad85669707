#include "solver/workspace.h"

#include <filesystem>
#include <fstream>
#include <set>

#include "geometry/atomic_output.h"
#include "geometry/errors.h"

namespace sdog {
namespace {

using nlohmann::json;
constexpr const char* kFormat = "sdog-workspace";
constexpr int kVersion = 1;

[[noreturn]] void fail(const std::string& source, const std::string& path, const std::string& what) {
  throw InputError(source + ": " + path + ": " + what);
}

Eigen::Vector3d vec3(const json& j, const std::string& source, const std::string& path) {
  if (!j.is_array() || j.size() != 3) fail(source, path, "expected an array of 3 numbers");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    if (!j[i].is_number()) fail(source, path, "expected an array of 3 numbers");
    v[i] = j[i].get<double>();
    if (!std::isfinite(v[i])) fail(source, path, "expected finite numbers");
  }
  return v;
}

int index(const json& j, const std::string& source, const std::string& path) {
  if (!j.is_number_integer() || j.get<long long>() < 0) fail(source, path, "expected an index (an integer >= 0)");
  return j.get<int>();
}

const json& member(const json& j, const char* key, const std::string& source, const std::string& path) {
  if (!j.is_object() || !j.contains(key)) fail(source, path, std::string("missing \"") + key + "\"");
  return j.at(key);
}

std::string text(const json& j, const char* key, const std::string& source) {
  const json& v = member(j, key, source, "$");
  if (!v.is_string()) fail(source, std::string("$.") + key, "expected a string");
  return v.get<std::string>();
}

}  // namespace

Workspace workspace_of(const Session& session, const std::string& pattern, const std::string& resolution,
                       const nlohmann::json& camera) {
  Workspace w;
  w.pattern = pattern;
  w.resolution = resolution;
  w.mode = session.mode();
  w.iteration = session.iteration();
  w.config = session.config();
  w.constraints = session.constraints();
  w.camera = camera;
  w.positions = session.positions();
  return w;
}

json to_json(const Workspace& w) {
  json config = to_json(w.config);
  if (config["admm"]["p"].is_string()) config["admm"].erase("p");  // the default, a formula
  json handles = json::array(), angles = json::array(), positions = json::array();
  for (const auto& h : w.constraints.handles)
    handles.push_back({{"vertex", h.vertex}, {"target", {h.target.x(), h.target.y(), h.target.z()}}});
  for (const auto& a : w.constraints.angles) angles.push_back({{"crease_point", a.crease_point}, {"degrees", a.degrees}});
  for (Eigen::Index v = 0; v < w.positions.size() / 3; ++v)
    positions.push_back({w.positions[3 * v], w.positions[3 * v + 1], w.positions[3 * v + 2]});
  return {{"format", kFormat},   {"version", kVersion},   {"pattern", w.pattern},     {"resolution", w.resolution},
          {"mode", w.mode},      {"iteration", w.iteration}, {"config", config},      {"handles", handles},
          {"angles", angles},    {"camera", w.camera},    {"positions", positions}};
}

Workspace workspace_from_json(const json& j, const std::string& source) {
  if (!j.is_object()) fail(source, "$", "expected a JSON object");
  if (!j.contains("format") || j["format"] != kFormat)
    fail(source, "$.format", std::string("not a workspace (expected \"") + kFormat + "\")");
  if (!j.contains("version") || j["version"] != kVersion)
    fail(source, "$.version", "unsupported version (this program reads version " + std::to_string(kVersion) + ")");
  for (const auto& [key, value] : j.items()) {
    static const std::set<std::string> known = {"format", "version", "pattern", "resolution", "mode", "iteration",
                                                "config", "handles", "angles", "camera", "positions"};
    if (!known.count(key)) fail(source, "$." + key, "unknown key");
  }
  Workspace w;
  w.pattern = text(j, "pattern", source);
  w.resolution = text(j, "resolution", source);
  w.mode = text(j, "mode", source);
  if (j.contains("iteration")) w.iteration = index(j["iteration"], source, "$.iteration");
  if (j.contains("config")) apply_run_config(j["config"], source + " ($.config)", w.config);
  if (j.contains("handles")) {
    const json& list = j["handles"];
    if (!list.is_array()) fail(source, "$.handles", "expected an array");
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string p = "$.handles[" + std::to_string(i) + "]";
      w.constraints.handles.push_back({index(member(list[i], "vertex", source, p), source, p + ".vertex"),
                                       vec3(member(list[i], "target", source, p), source, p + ".target")});
    }
  }
  if (j.contains("angles")) {
    const json& list = j["angles"];
    if (!list.is_array()) fail(source, "$.angles", "expected an array");
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string p = "$.angles[" + std::to_string(i) + "]";
      const json& d = member(list[i], "degrees", source, p);
      if (!d.is_number() || !(std::abs(d.get<double>()) <= 180)) fail(source, p + ".degrees", "expected degrees in [-180, 180]");
      w.constraints.angles.push_back({index(member(list[i], "crease_point", source, p), source, p + ".crease_point"),
                                      d.get<double>()});
    }
  }
  if (j.contains("camera")) w.camera = j["camera"];
  if (j.contains("positions")) {
    const json& list = j["positions"];
    if (!list.is_array()) fail(source, "$.positions", "expected an array");
    w.positions.resize(3 * static_cast<Eigen::Index>(list.size()));
    for (size_t v = 0; v < list.size(); ++v)
      w.positions.segment<3>(3 * v) = vec3(list[v], source, "$.positions[" + std::to_string(v) + "]");
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
  if (pattern.is_relative()) w.pattern = (std::filesystem::path(path).parent_path() / pattern).lexically_normal().string();
  return w;
}

}  // namespace sdog
