#include "solver/session/session.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "base/errors.h"
#include "solver/modes/mode_factory.h"
#include "solver/problem/fold_seed.h"
#include "solver/run/crease_settings.h"
#include "solver/run/run_setup.h"

namespace sdog {

Session::Session(const DogModel& model, const RunConfig& config, ModeKind mode)
    : source_(model), model_(model), config_(config), mode_kind_(mode) {
  check_mode_usable(mode, model);
  apply_creases();
  x_ = origin_ = base_.start(model_.fine);
  rebuild();
}

Session::~Session() = default;

void Session::apply_creases() {
  for (size_t k = 0; k < model_.clean.creases.size(); ++k) {
    model_.clean.creases[k].fold = source_.clean.creases[k].fold;
    model_.clean.creases[k].angle = source_.clean.creases[k].angle;
  }
  for (const auto& [to, from] :
       {std::pair{&model_.fine, &source_.fine}, std::pair{&model_.coarse, &source_.coarse}})
    for (size_t k = 0; k < to->stitching.curves.size(); ++k) {
      to->stitching.curves[k].fold = from->stitching.curves[k].fold;
      to->stitching.curves[k].angle = from->stitching.curves[k].angle;
    }
  apply_crease_settings(config_.creases, model_);
  base_ = make_scenario(config_, model_.fine);
  mode_.reset();  // before the problem it refers to
  problem_ = std::make_unique<DogProblem>(model_.fine, model_.fine_topology, config_.weights);
}

void Session::rebuild() {
  scenario_ = base_;
  // A handle on a vertex replaces the base scenario's target for it.
  auto& base = scenario_.positions;
  base.erase(std::remove_if(base.begin(), base.end(),
                            [&](const auto& p) {
                              return std::any_of(user_.handles.begin(), user_.handles.end(),
                                                 [&](const UserConstraints::Handle& h) {
                                                   return h.vertex == p.vertex;
                                                 });
                            }),
             base.end());
  for (const auto& h : user_.handles) scenario_.positions.push_back({h.vertex, h.target, h.target});
  for (const auto& a : user_.angles)
    scenario_.angles.push_back({a.crease_point, a.degrees, a.degrees});
  mode_ =
      switch_mode(mode_kind_, *problem_, scenario_, config_, config_.weights, model_, x_, &origin_);
}

IterationReport Session::step() {
  const IterationReport report =
      run_iteration(*mode_, *problem_, scenario_, x_, iteration_ + 1, IterationContext::kOpenEnded);
  if (!report.step.failed) ++iteration_;
  return report;
}

void Session::reset() {
  x_ = origin_ = base_.start(model_.fine);
  iteration_ = 0;
  rebuild();
}

void Session::set_mode(ModeKind mode) {
  check_mode_usable(mode, model_);
  mode_kind_ = mode;
  rebuild();
}

void Session::set_positions(const Dofs& x, int iteration) {
  if (x.size() != x_.size())
    throw InputError("positions for " + std::to_string(x.size() / 3) + " vertices, the mesh has " +
                     std::to_string(x_.size() / 3));
  if (!x.allFinite()) throw InputError("positions that are not finite numbers");
  x_ = x;
  iteration_ = iteration;
  rebuild();
}

void Session::check_vertex(int vertex) const {
  if (vertex < 0 || vertex >= model_.fine.vertex_count())
    throw InputError("vertex " + std::to_string(vertex) + " does not exist (the fine mesh has " +
                     std::to_string(model_.fine.vertex_count()) + " vertices)");
}

void Session::edit(const UserConstraints& next, const std::string& name, bool merge) {
  if (!merge || undo_.empty()) undo_.push_back({user_, config_.creases, name});
  redo_.clear();
  user_ = next;
  rebuild();
}

int Session::add_handle(int vertex) {
  return add_handles({vertex});
}

int Session::add_handles(const std::vector<int>& vertices) {
  if (vertices.empty()) throw InputError("no vertices to make handles of");
  for (int v : vertices) check_vertex(v);
  const int first = static_cast<int>(user_.handles.size());
  UserConstraints next = user_;
  for (int v : vertices) next.handles.push_back({v, Eigen::Vector3d(vertex_of(x_, v))});
  edit(next, vertices.size() == 1 ? "make handle"
                                  : "make " + std::to_string(vertices.size()) + " handles");
  return first;
}

int Session::add_handle_at(int vertex, const Eigen::Vector3d& target) {
  check_vertex(vertex);
  if (!target.allFinite()) throw InputError("a handle target that is not finite");
  UserConstraints next = user_;
  next.handles.push_back({vertex, target});
  edit(next, "take the scenario's target of vertex " + std::to_string(vertex));
  return static_cast<int>(user_.handles.size()) - 1;
}

void Session::move_handle(int handle, const Eigen::Vector3d& target, bool merge) {
  if (handle < 0 || handle >= static_cast<int>(user_.handles.size()))
    throw InputError("handle " + std::to_string(handle) + " does not exist");
  if (!target.allFinite()) throw InputError("a handle target that is not finite");
  UserConstraints next = user_;
  next.handles[handle].target = target;
  edit(next, "move handle " + std::to_string(handle), merge);
}

void Session::remove_handle(int handle) {
  if (handle < 0 || handle >= static_cast<int>(user_.handles.size()))
    throw InputError("handle " + std::to_string(handle) + " does not exist");
  UserConstraints next = user_;
  next.handles.erase(next.handles.begin() + handle);
  edit(next, "remove handle " + std::to_string(handle));
}

int Session::add_angle(int crease_point, double degrees) {
  const auto& points = model_.fine.stitching.points;
  if (crease_point < 0 || crease_point >= static_cast<int>(points.size()))
    throw InputError("crease point " + std::to_string(crease_point) +
                     " does not exist (there are " + std::to_string(points.size()) + ")");
  if (points[crease_point].copies.size() != 2)
    throw InputError("crease point " + std::to_string(crease_point) + " lies between " +
                     std::to_string(points[crease_point].copies.size()) +
                     " patches; a dihedral angle needs exactly two");
  if (!find_fold_site(problem_->sites, crease_point))
    throw InputError("crease point " + std::to_string(crease_point) +
                     " is no fold site (it lies on a grid vertex or at the end of its crease)");
  if (!(std::abs(degrees) <= 180))
    throw InputError("a dihedral angle must be in [-180, 180] degrees");
  // A flat sheet is a symmetric point of the angle constraint (no out-of-plane gradient): tilt it
  // towards the requested fold first, as the fold scenario's start state does.
  if ((x_ - problem_->rest()).lpNorm<Eigen::Infinity>() < 1e-12) {
    std::vector<double> signs(model_.fine.stitching.curves.size(), 0.0);
    for (size_t c = 0; c < signs.size(); ++c)
      for (int p : model_.fine.stitching.curves[c].points)
        if (p == crease_point) signs[c] = degrees >= 0 ? 1.0 : -1.0;
    x_ = origin_ = fold_seed(model_.fine, signs);
  }
  UserConstraints next = user_;
  next.angles.push_back({crease_point, degrees});
  edit(next, "add angle constraint");
  return static_cast<int>(user_.angles.size()) - 1;
}

void Session::remove_angle(int angle) {
  if (angle < 0 || angle >= static_cast<int>(user_.angles.size()))
    throw InputError("angle constraint " + std::to_string(angle) + " does not exist");
  UserConstraints next = user_;
  next.angles.erase(next.angles.begin() + angle);
  edit(next, "remove angle constraint");
}

void Session::set_constraints(const UserConstraints& constraints) {
  for (const auto& h : constraints.handles) check_vertex(h.vertex);
  edit(constraints, "set the constraints");
}

void Session::set_creases(const std::vector<int>& curves, std::optional<Fold> fold,
                          std::optional<double> angle) {
  const auto& existing = model_.fine.stitching.curves;
  if (curves.empty()) throw InputError("no crease to set: pick one first");
  for (int k : curves)
    if (k < 0 || k >= static_cast<int>(existing.size()))
      throw InputError("crease " + std::to_string(k) + " does not exist (the pattern has " +
                       std::to_string(existing.size()) + " creases after cleaning)");
  for (int k : curves) check_foldable(model_.fine, k, "studio");
  if (angle && !(*angle >= 0 && *angle <= 180))
    throw InputError("a fold angle must be in [0, 180] degrees");
  if (!fold && !angle) return;
  const std::string what =
      fold ? enum_name(*fold) : std::to_string(static_cast<int>(std::lround(*angle))) + " degrees";
  undo_.push_back({user_, config_.creases,
                   (curves.size() == 1 ? "set crease " + std::to_string(curves[0])
                                       : "set " + std::to_string(curves.size()) + " creases") +
                       " " + what});
  redo_.clear();
  for (int k : curves) {
    // The crease's whole state after the edit, as apply_crease_settings would leave it.
    CreaseSetting s;
    s.path = "studio: crease " + std::to_string(k);
    s.curve = k;
    s.fold = fold.value_or(existing[k].fold);
    s.angle = existing[k].angle;
    if (fold && *fold != Fold::kMountain && *fold != Fold::kValley) s.angle.reset();
    if (angle) s.angle = angle;
    // A setting with the whole state makes the studio's earlier ones for the crease redundant
    // (one with an assignment and no angle keeps the angle before it: those stay).
    if (s.angle || (*s.fold != Fold::kMountain && *s.fold != Fold::kValley)) {
      auto& list = config_.creases;
      list.erase(std::remove_if(list.begin(), list.end(),
                                [&](const CreaseSetting& c) {
                                  return c.curve == k && !c.id && c.path.rfind("studio: ", 0) == 0;
                                }),
                 list.end());
    }
    config_.creases.push_back(s);
  }
  apply_creases();
  rebuild();
}

void Session::fold() {
  RunConfig next = config_;
  next.scenario = ScenarioKind::kFold;
  Scenario scenario = make_scenario(next, model_.fine);
  check_scenario_targets(scenario, next, "the pattern at this resolution");
  config_ = next;
  base_ = std::move(scenario);
  reset();
}

void Session::set_fold_percent(double percent) {
  if (!(percent >= 0 && percent <= 100)) throw InputError("a fold amount is from 0 to 100 percent");
  config_.fold_percent = percent;
  if (config_.scenario != ScenarioKind::kFold) {
    fold();
    return;
  }
  base_ = make_scenario(config_, model_.fine);
  rebuild();
}

bool Session::undo() {
  return travel(undo_, redo_);
}
bool Session::redo() {
  return travel(redo_, undo_);
}

bool Session::travel(std::vector<EditState>& from, std::vector<EditState>& to) {
  if (from.empty()) return false;
  to.push_back({user_, config_.creases, from.back().name});
  user_ = from.back().user;
  const bool creases_change = config_.creases != from.back().creases;
  config_.creases = from.back().creases;
  from.pop_back();
  if (creases_change)
    apply_creases();  // the problem and scenario are rebuilt only when they change
  rebuild();
  return true;
}

}  // namespace sdog
