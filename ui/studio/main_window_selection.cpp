// MainWindow: selecting vertices and creases, clicking in the view, editing creases, the
// inspectors.
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
#include "ui/control/crease_edit.h"
#include "ui/control/screen_pick.h"
#include "ui/control/selection.h"
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

void MainWindow::select_vertex(int vertex) {
  select_vertices(vertex >= 0 ? std::vector<int>{vertex} : std::vector<int>{});
}

int MainWindow::crease_count() const {
  return model_ ? static_cast<int>(model_->fine.stitching.curves.size()) : 0;
}

void MainWindow::select_vertices(const std::vector<int>& vertices, bool add) {
  selection_.select_vertices(vertices, add);
  refresh_selection_marks();
  show_in_inspector(-1);
}

void MainWindow::select_creases(const std::vector<int>& creases, bool add) {
  selection_.select_creases(creases, crease_count(), add);
  refresh_selection_marks();
  show_in_inspector(-1);
}

void MainWindow::click(double x, double y) {
  if (!snapshot_) return;
  Eigen::MatrixX3d crease_points(0, 3);
  if (scene_->layer_on(vis::Layer::kCreaseCurves)) {
    const auto points = vis::crease_point_positions(model_->fine, shown_positions());
    Eigen::MatrixX3d rows(points.size(), 3);
    for (size_t p = 0; p < points.size(); ++p) rows.row(p) = points[p].transpose();
    crease_points = project_to_display(renderer_, rows);
  }
  const control::ClickPick pick = control::pick_at(
      model_->fine, crease_points, project_to_display(renderer_, shown_positions()), x, y);
  selection_.apply(pick, crease_count());
  refresh_selection_marks();
  show_in_inspector(-1);
  status_->setText(QString::fromStdString(pick.message));
}

bool MainWindow::edit_creases(std::optional<Fold> fold, std::optional<double> angle) {
  const std::vector<int> creases = selection_.creases();
  std::string message;
  if (!attempt(
          [&] { message = control::crease_edit_message(creases, fold, angle, config_.scenario); }))
    return false;
  post([creases, fold, angle](SolverWorker& w) { w.set_creases(creases, fold, angle); });
  status_->setText(QString::fromStdString(message));
  return true;
}

void MainWindow::set_crease_fold(Fold fold) {
  edit_creases(fold, std::nullopt);
}

void MainWindow::set_crease_angle(double degrees) {
  edit_creases(std::nullopt, degrees);
}

void MainWindow::fold_creases() {
  if (!worker_) {
    report_error("Open a crease pattern first (File > Open pattern).");
    return;
  }
  chart_->clear();
  post([](SolverWorker& w) { w.fold(); });
  status_->setText(
      "folding from the flat sheet with the crease assignments (Solver > Play: Space)");
}

void MainWindow::set_fold_percent(int percent) {
  if (!worker_) {
    report_error("Open a crease pattern first (File > Open pattern).");
    show_solver_state();
    return;
  }
  config_.fold_percent = percent;
  if (config_.scenario != ScenarioKind::kFold) {
    config_.scenario = ScenarioKind::kFold;
    chart_->clear();
  }
  show_solver_state();
  post([percent](SolverWorker& w) { w.set_fold_percent(percent); });
  status_->setText(QString("folding to %1% of the crease angles").arg(percent));
}

void MainWindow::select_in_rectangle(double x0, double y0, double x1, double y1, bool add) {
  if (!snapshot_) return;
  select_vertices(
      control::inside_rectangle(project_to_display(renderer_, shown_positions()), x0, y0, x1, y1),
      add);
}

Eigen::MatrixX3d MainWindow::shown_positions() const {
  if (scene_options_.view == vis::View::kFlat) return model_->fine.V;
  return snapshot_->state.fine;
}

void MainWindow::refresh_selection_marks() {
  if (snapshot_)
    marks_->show_points(shown_positions(), selection_.vertices());
  else
    marks_->show_points(Eigen::MatrixX3d(0, 3), {});
  render();
}

void MainWindow::show_in_inspector(int hovered) {
  hovered_vertex_ = hovered;
  const int vertex = hovered >= 0 ? hovered : selection_.vertex();
  if (vertex < 0 && !selection_.creases().empty() && model_ && snapshot_) {
    attempt([&] {
      inspector_->setText("<i>picked</i><br>" +
                          describe_creases(*model_, snapshot_->state.crease_folds,
                                           snapshot_->crease_angles, config_.fold_angle,
                                           selection_.creases()));
    });
    return;
  }
  if (vertex < 0 || !model_ || !snapshot_) {
    inspector_->setText("Click a vertex to pick it, or point at one to inspect it.");
    return;
  }
  attempt([&] {
    inspector_->setText(
        (hovered >= 0 ? QString("<i>under the mouse</i>") : QString("<i>picked</i>")) +
        describe_vertex(*model_, snapshot_->state, vertex));
  });
}

}  // namespace sdog::studio
