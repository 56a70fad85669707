#include "ui/studio/solver_worker.h"

#include <QMetaObject>
#include <QThread>

#include <algorithm>
#include <exception>

#include "base/errors.h"

namespace sdog::studio {

SolverWorker::SolverWorker(std::shared_ptr<const DogModel> model)
    : model_(std::move(model)), play_timer_(new QTimer(this)) {
  play_timer_->setInterval(0);
  connect(play_timer_, &QTimer::timeout, this, [this] {
    if (hold_ && !snapshot_taken_) {  // a state to record is not shown yet
      QThread::msleep(1);
      return;
    }
    hold_ = false;
    try {
      step();
    } catch (const std::exception& e) {
      pause();
      Q_EMIT failed(QString::fromStdString(e.what()));
    }
  });
}

SolverWorker::~SolverWorker() = default;

void SolverWorker::post(std::function<void(SolverWorker&)> command) {
  QMetaObject::invokeMethod(
      this,
      [this, command = std::move(command)] {
        try {
          command(*this);
        } catch (const std::exception& e) {
          Q_EMIT failed(QString::fromStdString(e.what()));
          if (session_) send_snapshot();
        }
      },
      Qt::QueuedConnection);
}

Session& SolverWorker::session() {
  if (!session_) throw UsageError("no pattern is open");
  return *session_;
}

void SolverWorker::send_snapshot() {
  const Session& s = *session_;
  Snapshot snap;
  snap.state =
      vis::scene_state(s.problem(), s.positions(), s.coarse_positions(), &s.scenario(), s.time());
  snap.iteration = s.iteration();
  snap.mode = enum_name(s.mode());
  snap.constraints = s.constraints();
  for (const auto& c : s.model().fine.stitching.curves) {
    snap.state.crease_folds.push_back(c.fold);
    snap.crease_angles.push_back(c.angle);
  }
  snap.crease_settings = s.config().creases;
  snap.scenario = s.config().scenario;
  snap.can_undo = s.can_undo();
  snap.can_redo = s.can_redo();
  snap.undo_name = s.undo_name();
  snap.redo_name = s.redo_name();
  snap.time = s.time();
  snap.scenario_done = s.scenario_done();
  snapshot_taken_ = false;
  Q_EMIT snapshot_ready(snap);
}

void SolverWorker::open(const RunConfig& config, const std::string& mode,
                        const std::optional<Workspace>& state) {
  pause();
  session_.reset();
  session_ = std::make_unique<Session>(*model_, config, parse_enum<ModeKind>(mode));
  if (state) {
    if (!state->constraints.handles.empty() || !state->constraints.angles.empty())
      session_->set_constraints(state->constraints);
    if (state->positions.size() > 0) session_->set_positions(state->positions, state->iteration);
  }
  send_snapshot();
}

void SolverWorker::step() {
  const IterationReport report = session().step();
  Q_EMIT iterated(report);
  if (report.step.failed) {
    pause();
    send_snapshot();
    throw SolverError(
        "iteration " + std::to_string(report.iteration) + " failed: " + report.step.failure +
        ". The sheet stays at the last good state: undo the last edit (Ctrl+Z), move the handle a "
        "shorter way, or reset the solver (Ctrl+Backspace).");
  }
  if (play_timer_->isActive() && session_->scenario_done() &&
      report.step.converged.value_or(false)) {
    pause();  // sends the snapshot
    stopped_converged_ = true;
    Q_EMIT stopped_converged();
    return;
  }
  // While playing, a state the window has not taken yet is replaced by the next one, unless the
  // window records this one.
  const bool record = record_every_ > 0 && session_->iteration() % record_every_ == 0;
  if (!play_timer_->isActive() || snapshot_taken_ || record) {
    send_snapshot();
    hold_ = record;
  }
}

void SolverWorker::set_recording(int every) {
  record_every_ = std::max(0, every);
  hold_ = false;
}

void SolverWorker::reopen(const RunConfig& config, const std::string& mode, bool keep_shape) {
  std::optional<Workspace> state;
  if (keep_shape && session_) state = workspace_of(*session_, "", "", nlohmann::json());
  open(config, mode, state);
}

void SolverWorker::play() {
  session();
  stopped_converged_ = false;
  if (play_timer_->isActive()) return;
  play_timer_->start();
  Q_EMIT playing_changed(true);
}

void SolverWorker::play_on() {
  if (stopped_converged_) play();
}

void SolverWorker::pause() {
  stopped_converged_ = false;
  if (!play_timer_->isActive()) return;
  play_timer_->stop();
  Q_EMIT playing_changed(false);
  if (session_) send_snapshot();
}

void SolverWorker::reset() {
  session().reset();
  send_snapshot();
}

void SolverWorker::set_mode(const std::string& mode) {
  session().set_mode(parse_enum<ModeKind>(mode));
  send_snapshot();
}

void SolverWorker::add_handles(const std::vector<int>& vertices) {
  session().add_handles(vertices);
  play_on();
  send_snapshot();
}

void SolverWorker::add_handle_at(int vertex, const Eigen::Vector3d& target) {
  session().add_handle_at(vertex, target);
  play_on();
  send_snapshot();
}

void SolverWorker::drag_handle(int handle, const Eigen::Vector3d& target, bool first) {
  std::lock_guard<std::mutex> lock(drag_mutex_);
  if (drag_) {  // not applied yet: replaced (a first move stays a first move)
    drag_->handle = handle;
    drag_->target = target;
    drag_->first = drag_->first || first;
    return;
  }
  drag_ = Drag{handle, target, first};
  post([](SolverWorker& w) { w.apply_drag(); });
}

void SolverWorker::apply_drag() {
  Drag d;
  {
    std::lock_guard<std::mutex> lock(drag_mutex_);
    if (!drag_) return;
    d = *drag_;
    drag_.reset();
  }
  session().move_handle(d.handle, d.target, /*merge=*/!d.first);
  play_on();
  send_snapshot();
}

void SolverWorker::move_handle(int handle, const Eigen::Vector3d& target) {
  session().move_handle(handle, target);
  play_on();
  send_snapshot();
}

void SolverWorker::remove_handle(int handle) {
  session().remove_handle(handle);
  play_on();
  send_snapshot();
}

void SolverWorker::add_angle(int crease_point, double degrees) {
  session().add_angle(crease_point, degrees);
  play_on();
  send_snapshot();
}

void SolverWorker::remove_angle(int angle) {
  session().remove_angle(angle);
  play_on();
  send_snapshot();
}

void SolverWorker::set_creases(const std::vector<int>& curves, std::optional<Fold> fold,
                               std::optional<double> angle) {
  session().set_creases(curves, fold, angle);
  play_on();
  send_snapshot();
}

void SolverWorker::fold() {
  session().fold();
  send_snapshot();
}

void SolverWorker::set_fold_percent(double percent) {
  session().set_fold_percent(percent);
  play();
  send_snapshot();
}

void SolverWorker::undo() {
  session().undo();
  play_on();
  send_snapshot();
}

void SolverWorker::redo() {
  session().redo();
  play_on();
  send_snapshot();
}

void SolverWorker::save_workspace(const std::string& path, const std::string& pattern,
                                  const std::string& resolution, const nlohmann::json& camera) {
  sdog::save_workspace(workspace_of(session(), pattern, resolution, camera), path);
  Q_EMIT workspace_saved(QString::fromStdString(path));
}

}  // namespace sdog::studio
