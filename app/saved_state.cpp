#include "app/saved_state.h"

#include <filesystem>
#include <regex>

#include "base/errors.h"
#include "solver/problem/dog_problem.h"
#include "solver/run/crease_settings.h"
#include "solver/run/run_setup.h"

namespace sdog::cli {
namespace {

namespace fs = std::filesystem;

// The iteration of a frame file: its entry in the frames.pvd beside it, or its name frame_NNNN.vtu.
std::optional<int> frame_iteration(const std::string& frame) {
  const fs::path pvd = fs::path(frame).parent_path() / "frames.pvd";
  if (fs::is_regular_file(pvd)) {
    try {
      for (const vis::FrameEntry& e : vis::read_frame_list(pvd.string())) {
        std::error_code error;
        if (fs::equivalent(e.path, frame, error)) return e.iteration;
      }
    } catch (const InputError&) {
      // Not a list of frames after all: the name may still say the iteration.
    }
  }
  static const std::regex name("frame_([0-9]{1,9})\\.vtu");
  std::smatch m;
  const std::string file = fs::path(frame).filename().string();
  if (std::regex_match(file, m, name)) return std::stoi(m[1]);
  return std::nullopt;
}

}  // namespace

SavedState load_saved_state(const SavedStateRequest& r) {
  SavedState s;
  fs::path dir;
  if (!r.run.empty()) {
    if (!fs::is_directory(r.run))
      throw InputError(r.run + (fs::exists(r.run)
                                    ? ": not a directory (--run takes the folder of sdog run --out)"
                                    : ": no such directory"));
    const std::string pvd = (fs::path(r.run) / "frames.pvd").string();
    if (!fs::exists(pvd))
      throw InputError(r.run +
                       ": no frames.pvd, so no saved frames (sdog run --out writes them unless "
                       "--frames-every 0)");
    const vis::FrameEntry entry = vis::find_frame(vis::read_frame_list(pvd), r.iteration, pvd);
    s.frame = entry.path;
    s.iteration = entry.iteration;
    dir = r.run;
  } else {
    s.frame = r.frame;
    dir = fs::path(r.frame).parent_path();
  }
  s.data = vis::read_frame(s.frame);
  if (r.run.empty()) s.iteration = frame_iteration(s.frame);

  const fs::path record = (dir.empty() ? fs::path(".") : dir) / "run.json";
  if (fs::exists(record))
    s.run = read_saved_run(record.string());
  else if (!r.given("PATTERN"))
    throw InputError(
        (r.run.empty() ? r.frame + ": no run.json beside it" : r.run + ": no run.json") +
        " to say which pattern and resolution the frame belongs to (sdog run --out writes one): "
        "give "
        "PATTERN and --res");

  s.pattern = s.run ? s.run->pattern : r.command_line;
  bool overridden = !s.run;
  auto take = [&](const char* option, auto member) {
    if (!s.run || !r.given(option)) return;
    s.pattern.*member = r.command_line.*member;
    overridden = true;
  };
  take("PATTERN", &PatternOptions::pattern);
  take("--res", &PatternOptions::res);
  take("--flatness", &PatternOptions::flatness);
  take("--merge-tol", &PatternOptions::merge_fraction);
  take("--snap-tol", &PatternOptions::snap_fraction);
  take("--fine-only", &PatternOptions::fine_only);
  if (s.run && !r.given("PATTERN") && !fs::is_regular_file(s.pattern.pattern))
    throw InputError(
        s.run->record + ": the run's pattern " + s.pattern.pattern +
        " is not there any more (moved or deleted?): give the pattern file as PATTERN");
  s.model_source = overridden ? std::string("as given on the command line")
                              : "as " + s.run->record + " records it";
  return s;
}

DogModel saved_state_model(const SavedState& s) {
  DogModel model = build_model(s.pattern);
  vis::check_frame_of(
      s.data, model.fine, s.frame,
      s.pattern.pattern + " at " + model.fine_res.str() + " (" + s.model_source + ")");
  if (s.run) apply_crease_settings(s.run->config.creases, model);
  return model;
}

RunConfig saved_state_config(const SavedState& s, ScenarioKind scenario) {
  if (s.run) return s.run->config;
  RunConfig config;
  config.scenario = scenario;
  return config;
}

Workspace saved_workspace(const SavedState& s, const DogModel& model,
                          const std::optional<std::string>& mode) {
  Workspace w;
  w.pattern = s.pattern.pattern;
  w.resolution = model.fine_res.str();
  w.iteration = s.iteration.value_or(0);
  w.mode = mode ? *mode : s.run ? s.run->mode_at(w.iteration) : enum_name(ModeKind::kStandard);
  w.config = saved_state_config(s, ScenarioKind::kCorners);
  w.positions = to_dofs(s.data.positions);
  return w;
}

vis::SceneState saved_scene_state(const SavedState& s, const DogModel& model,
                                  const RunConfig& config, bool constraints) {
  const DogProblem problem(model.fine, model.fine_topology, config.weights);
  const Dofs x = to_dofs(s.data.positions);
  if (!constraints) return vis::scene_state(problem, x);
  const Scenario scenario = make_scenario(config, model.fine);
  // The targets of iteration k are those at the scenario's time of k (0 for the start state).
  const double t =
      s.run && s.iteration ? (*s.iteration > 0 ? scenario.time_of(*s.iteration) : 0.0) : 1.0;
  return vis::scene_state(problem, x, nullptr, &scenario, t);
}

}  // namespace sdog::cli
