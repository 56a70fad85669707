#pragma once
// Workspaces (the studio's File > Open/Save Workspace): one JSON file with everything needed to
// come back to a session: the pattern file, the resolution, the mode, the run configuration (as
// `sdog run --config` reads it), the user's constraints, the camera and the current positions.
//
//   {"format": "sdog-workspace", "version": 1,
//    "pattern": "four_corner_arcs.svg",          (relative paths are relative to the workspace
//    file) "resolution": "21x21", "mode": "standard", "iteration": 40, "config": {...run
//    configuration...}, "handles": [{"vertex": 12, "target": [x, y, z]}], "angles":
//    [{"crease_point": 3, "degrees": 60}], "camera": {...} or null,                     (the view's
//    own format; kept as it is) "positions": [[x, y, z], ...]}               (fine vertices; empty:
//    the start state)
#include <nlohmann/json.hpp>
#include <string>

#include "solver/run/run_config.h"
#include "solver/session/session.h"

namespace sdog {

struct Workspace {
  std::string pattern;
  std::string resolution;
  std::string mode = "standard";
  int iteration = 0;
  RunConfig config;
  UserConstraints constraints;
  nlohmann::json camera;  ///< null: none saved
  Dofs positions;         ///< empty: the start state
};

/// The workspace of a session (pattern path and resolution given by the caller).
Workspace workspace_of(const Session& session, const std::string& pattern,
                       const std::string& resolution, const nlohmann::json& camera);

nlohmann::json to_json(const Workspace& w);
/// Throws InputError naming `source` and the JSON path of what is wrong.
Workspace workspace_from_json(const nlohmann::json& j, const std::string& source);

/// Writes the file under a temporary name and renames it; throws OutputError naming the path.
void save_workspace(const Workspace& w, const std::string& path);
/// Reads and checks a workspace file; a relative pattern path becomes relative to the file's
/// directory. Throws InputError naming the file.
Workspace load_workspace(const std::string& path);

}  // namespace sdog
