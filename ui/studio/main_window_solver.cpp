// MainWindow: the Solver and Edit commands, sent to the solver thread (its results come back as
// snapshots), and the run configuration.
#include "ui/studio/main_window.h"

#include <QVTKOpenGLNativeWidget.h>
#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QStatusBar>
#include <QtGlobal>
#include <algorithm>
#include <exception>

#include "base/errors.h"
#include "solver/config/run_config_json.h"
#include "solver/modes/mode_factory.h"
#include "solver/modes/settling_plan.h"
#include "ui/control/exports.h"
#include "ui/studio/click_drag_style.h"
#include "ui/studio/crease_inspector.h"
#include "ui/studio/model_loader.h"
#include "ui/studio/objective_chart.h"
#include "ui/studio/screen_picking.h"
#include "ui/studio/selection_marks.h"
#include "ui/studio/solver_worker.h"
#include "ui/studio/vertex_inspector.h"
#include "ui/vis/camera.h"
#include "ui/vis/mesh_view.h"

namespace sdog::studio {

void MainWindow::step(int iterations) {
  post([iterations](SolverWorker& w) {
    for (int k = 0; k < iterations; ++k) w.step();
  });
}

void MainWindow::play() {
  post([](SolverWorker& w) { w.play(); });
}
void MainWindow::pause() {
  post([](SolverWorker& w) { w.pause(); });
}
void MainWindow::reset_solver() {
  chart_->clear();
  post([](SolverWorker& w) { w.reset(); });
}

bool MainWindow::set_mode(const QString& mode) {
  const std::string name = mode.toStdString();
  if (!attempt([&] {
        const ModeKind kind = parse_enum<ModeKind>(name, "mode: ");
        if (model_) check_mode_usable(kind, *model_);
      })) {
    update_actions();
    return false;
  }
  mode_ = name;
  if (worker_) post([name](SolverWorker& w) { w.set_mode(name); });
  update_actions();
  show_solver_state();
  return true;
}

bool MainWindow::set_scenario(const QString& scenario) {
  const std::string name = scenario.toStdString();
  RunConfig config = config_;
  if (!attempt([&] { config.scenario = parse_enum<ScenarioKind>(name, "scenario: "); }))
    return false;
  // A new base scenario starts the session again (the user's constraints go with it).
  return set_run_config(config);
}

bool MainWindow::choose_scenario(const QString& scenario) {
  if (snapshot_ && scenario.toStdString() != enum_name(config_.scenario) && left_start()) {
    const int answer =
        question_sink_(QString("Another scenario starts a new session from its start state: the "
                               "current shape (iteration %1) and "
                               "the handles and angle constraints go. Start the %2 scenario?")
                           .arg(snapshot_->iteration)
                           .arg(scenario),
                       {"Start it", "Cancel"});
    if (answer != 0) {
      update_actions();
      return false;
    }
  }
  return set_scenario(scenario);
}

bool MainWindow::left_start() const {
  return snapshot_ && (snapshot_->iteration > 0 || !snapshot_->constraints.handles.empty() ||
                       !snapshot_->constraints.angles.empty());
}

bool MainWindow::load_run_config(const QString& path) {
  RunConfig config;
  if (!attempt([&] { read_run_config(path.toStdString(), config); })) return false;
  if (!set_run_config(config)) return false;
  config_file_ = path;
  config_pattern_ = pattern_path_;  // none open: the next one
  return true;
}

bool MainWindow::set_run_config(const RunConfig& config, bool keep_shape) {
  if (!attempt([&] { validate_run_config(config, "solver settings"); })) return false;
  config_ = config;
  update_actions();
  show_solver_state();
  if (!worker_) return true;
  modified_ = true;
  if (!keep_shape) chart_->clear();
  const std::string mode = mode_;
  post([config, mode, keep_shape](SolverWorker& w) { w.reopen(config, mode, keep_shape); });
  return true;
}

bool MainWindow::apply_settings(const RunConfig& config) {
  bool keep = false;
  if (left_start()) {
    const int answer = question_sink_(
        QString("New solver settings start a new session. Apply them to the current shape "
                "(iteration %1, with its "
                "handles and angle constraints), or start again from the scenario's start state?")
            .arg(snapshot_->iteration),
        {"Keep the shape", "Start again", "Cancel"});
    if (answer == 2 || answer < 0) {
      status_->setText("settings not applied (Apply again to choose)");
      return false;
    }
    keep = answer == 0;
  }
  if (!set_run_config(config, keep)) return false;
  status_->setText(
      keep ? QString("settings applied to the shape of iteration %1").arg(snapshot_->iteration)
           : QString("settings applied: started again from the scenario's start state"));
  return true;
}

bool MainWindow::settle_unsaved(const QString& action) {
  if (!modified_ || !worker_) return true;
  const int answer = question_sink_(
      QString("The session has changes that are not saved in a workspace. Save them before %1?")
          .arg(action),
      {"Save...", "Discard", "Cancel"});
  if (answer == 1) return true;
  if (answer != 0) return false;
  const QString path = save_path_sink_("Save workspace", "Workspaces (*.json)");
  if (path.isEmpty()) return false;
  // Waits for the solver thread to write it.
  QEventLoop wait;
  bool saved = false;
  const auto on_saved = connect(this, &MainWindow::workspace_saved, &wait, [&] {
    saved = true;
    wait.quit();
  });
  const auto on_failed = connect(worker_, &SolverWorker::failed, &wait, [&] { wait.quit(); });
  if (save_workspace(path)) wait.exec();
  disconnect(on_saved);
  disconnect(on_failed);
  return saved;
}

void MainWindow::add_handle(int vertex) {
  add_handles({vertex});
}
void MainWindow::add_handles(const std::vector<int>& vertices) {
  post([vertices](SolverWorker& w) { w.add_handles(vertices); });
}
void MainWindow::move_handle(int handle, const Eigen::Vector3d& target) {
  post([handle, target](SolverWorker& w) { w.move_handle(handle, target); });
}
void MainWindow::drag_handle(int handle, const Eigen::Vector3d& target, bool first) {
  if (worker_) worker_->drag_handle(handle, target, first);
}
void MainWindow::remove_handle(int handle) {
  post([handle](SolverWorker& w) { w.remove_handle(handle); });
}
void MainWindow::add_angle(int point, double degrees) {
  post([point, degrees](SolverWorker& w) { w.add_angle(point, degrees); });
}
void MainWindow::remove_angle(int angle) {
  post([angle](SolverWorker& w) { w.remove_angle(angle); });
}
void MainWindow::undo() {
  post([](SolverWorker& w) { w.undo(); });
}
void MainWindow::redo() {
  post([](SolverWorker& w) { w.redo(); });
}

}  // namespace sdog::studio
