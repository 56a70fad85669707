#include "solver/run/run_setup.h"

#include "base/errors.h"
#include "solver/modes/mode_factory.h"
#include "solver/run/crease_settings.h"
#include "solver/run/flatten_scenario.h"

namespace sdog {
namespace {

Scenario named_scenario(const RunConfig& c, const DogMesh& mesh) {
  switch (c.scenario) {
    case ScenarioKind::kCorners:
      return corners_scenario(mesh, c.iterations, c.hold);
    case ScenarioKind::kFold:
      return fold_scenario(mesh, c.fold_angle, c.iterations, c.hold, c.fold_percent);
    case ScenarioKind::kFlatten:
      return flatten_scenario(mesh, c.weights, c.standard, c.fold_angle, c.iterations, c.hold);
    case ScenarioKind::kNone:
      break;
  }
  Scenario s;
  s.name = "none";
  return s;
}

int resolve_vertex(const PositionSpec& p, const DogMesh& mesh) {
  if (p.vertex) {
    if (*p.vertex >= mesh.vertex_count())
      throw InputError(p.path + ".vertex: the fine mesh has " +
                       std::to_string(mesh.vertex_count()) + " vertices, there is no vertex " +
                       std::to_string(*p.vertex));
    return *p.vertex;
  }
  const Eigen::Vector2d target = mesh.to_mesh(*p.near);
  int v = -1;
  double best = 0;
  for (int u = 0; u < mesh.vertex_count(); ++u) {
    const double d = (mesh.V.row(u).head<2>().transpose() - target).squaredNorm();
    if (v < 0 || d < best) v = u, best = d;
  }
  return v;
}

void add_positions(const RunConfig& c, const DogMesh& mesh, Scenario& s) {
  for (const auto& p : c.positions) {
    PositionConstraint pc;
    pc.vertex = resolve_vertex(p, mesh);
    pc.start = p.start ? *p.start : Eigen::Vector3d(mesh.V.row(pc.vertex).transpose());
    pc.end = p.end ? *p.end : Eigen::Vector3d(pc.start + *p.move);
    s.positions.push_back(pc);
  }
}

// Angle constraints at one fold site or every fold site of a curve; each also sets its curve's fold
// direction for the start state (fold_seed.h).
void add_angles(const RunConfig& c, const DogMesh& mesh, Scenario& s) {
  const auto sites = fold_sites(mesh);
  s.curve_signs.resize(mesh.stitching.curves.size(), 0.0);
  auto set_sign = [&](int curve, double degrees) {
    if (degrees != 0) s.curve_signs[curve] = degrees > 0 ? 1.0 : -1.0;
  };
  for (const auto& a : c.angles) {
    if (a.point) {
      bool found = false;
      for (const auto& site : sites) found = found || site.point == *a.point;
      if (!found)
        throw InputError(a.path + ".crease_point: crease point " + std::to_string(*a.point) +
                         " is not a fold site (an interior crease point on an edge between two "
                         "patches; the mesh "
                         "has " +
                         std::to_string(sites.size()) +
                         " of them, see `sdog mesh --out` creases.vtp)");
      s.angles.push_back({*a.point, a.start_degrees, a.end_degrees});
      for (const auto& site : sites)
        if (site.point == *a.point) set_sign(site.curve, a.end_degrees);
    } else {
      for (const int curve : named_creases(mesh, a.curve, a.id, a.path)) {
        for (const auto& site : sites)
          if (site.curve == curve) s.angles.push_back({site.point, a.start_degrees, a.end_degrees});
        set_sign(curve, a.end_degrees);
      }
    }
  }
}

// The schedule of config.switches for run_scenario: at each switch's iteration the mode in
// `current` is replaced by switch_mode's (so `current` always owns the running mode).
ModeSchedule switch_schedule(DogProblem& problem, const Scenario& scenario, const RunConfig& config,
                             const DogModel& model, std::unique_ptr<Mode>& current) {
  return [&, next = size_t{0}](int k, const Dofs& x) mutable -> Mode* {
    if (next >= config.switches.size() || config.switches[next].iteration != k) return nullptr;
    current = switch_mode(config.switches[next++].mode, problem, scenario, config, config.weights,
                          model, x);
    return current.get();
  };
}

}  // namespace

Scenario make_scenario(const RunConfig& c, const DogMesh& mesh) {
  Scenario s = named_scenario(c, mesh);
  s.iterations = c.iterations;
  s.hold = c.hold;
  add_positions(c, mesh, s);
  add_angles(c, mesh, s);
  return s;
}

void check_scenario_targets(const Scenario& s, const RunConfig& c, const std::string& where) {
  if (!s.positions.empty() || !s.angles.empty()) return;
  if (c.scenario == ScenarioKind::kFold)
    throw UsageError(
        "the fold scenario found no fold sites in " + where +
        " (crease points strictly inside a grid edge between two patches; creases through grid "
        "vertices only have none: try another resolution)");
  throw UsageError(std::string("the run has no targets: scenario '") + enum_name(c.scenario) +
                   "' and no position or angle constraints in the configuration");
}

RunSetup::RunSetup(const DogModel& model, ModeKind mode, const RunConfig& config)
    : RunSetup(model, mode, config, make_scenario(config, model.fine)) {}

RunSetup::RunSetup(const DogModel& model, ModeKind mode, const RunConfig& config, Scenario scenario)
    : model_(model), config_(config), scenario_(std::move(scenario)) {
  problem_ = std::make_unique<DogProblem>(model.fine, model.fine_topology, config_.weights);
  check_scenario_targets(scenario_, config_, where());
  check_mode_usable(mode, model);
  for (const ModeSwitch& s : config_.switches) check_mode_usable(s.mode, model);
  mode_ = make_mode(mode, *problem_, scenario_, config_, &model);
  x_ = scenario_.start(model.fine);
}

RunSetup::~RunSetup() = default;

std::string RunSetup::where() const {
  return model_.pattern.source + " at " + model_.fine_res.str();
}

RunSummary RunSetup::run(const std::vector<RunObserver*>& observers,
                         const std::atomic<bool>* cancel) {
  return run_scenario(*mode_, *problem_, scenario_, x_, observers, cancel,
                      switch_schedule(*problem_, scenario_, config_, model_, mode_));
}

}  // namespace sdog
