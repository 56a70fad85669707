#include "app/saved_run.h"

#include <filesystem>

#include "base/errors.h"
#include "base/json_field.h"
#include "solver/config/run_config_json.h"
#include "solver/modes/mode_kind.h"

namespace sdog::cli {

void add_model_record(nlohmann::json& run_json, const PatternOptions& o) {
  run_json["pattern_path"] = std::filesystem::absolute(o.pattern).lexically_normal().string();
  run_json["mesh_options"] = {{"flatness", o.flatness},
                              {"merge_tol", o.merge_fraction},
                              {"snap_tol", o.snap_fraction},
                              {"fine_only", o.fine_only}};
}

std::string SavedRun::mode_at(int iteration) const {
  std::string current = mode;
  for (const ModeSwitch& s : config.switches)
    if (s.iteration <= iteration) current = enum_name(s.mode);
  return current;
}

SavedRun read_saved_run(const std::string& path) {
  const nlohmann::json j = read_json_file(path, "run record");
  const Field root(j, "$", path);
  if (!j.is_object()) root.fail("expected a JSON object (the run.json that sdog run --out writes)");
  for (const char* key : {"pattern", "resolution", "mode", "config"})
    if (!root.has(key))
      root.fail(std::string("missing \"") + key + "\": not a run.json of sdog run");
  SavedRun run;
  run.record = path;
  run.mode = root["mode"].text();
  if (!find_enum<ModeKind>(run.mode))
    root["mode"].fail("unknown mode '" + run.mode + "' (known: " + known_names<ModeKind>() + ")");
  apply_run_config(j["config"], path + " ($.config)", run.config);

  PatternOptions& o = run.pattern;
  const std::string given = root["pattern"].text();
  const std::string absolute = root.has("pattern_path") ? root["pattern_path"].text() : given;
  o.pattern = std::filesystem::is_regular_file(absolute) || !std::filesystem::is_regular_file(given)
                  ? absolute
                  : given;
  const Field res = root["resolution"];
  o.res = res["fine"].text();
  o.fine_only = res.has("coarse") && res["coarse"].text().empty();
  if (root.has("mesh_options")) {
    const Field m = root["mesh_options"];
    m.expect_object({"flatness", "merge_tol", "snap_tol", "fine_only"});
    if (m.has("flatness")) o.flatness = m["flatness"].positive();
    if (m.has("merge_tol")) o.merge_fraction = m["merge_tol"].non_negative();
    if (m.has("snap_tol")) o.snap_fraction = m["snap_tol"].non_negative();
    if (m.has("fine_only")) o.fine_only = m["fine_only"].boolean();
  }
  return run;
}

}  // namespace sdog::cli
