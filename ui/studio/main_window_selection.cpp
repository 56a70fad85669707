// MainWindow: selecting vertices and creases, clicking in the view, editing creases, the inspectors.
#include "ui/studio/main_window.h"

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
#include <QVTKOpenGLNativeWidget.h>
#include <QtGlobal>
#include <algorithm>
#include <exception>

#include "base/errors.h"
#include "solver/config/run_config_json.h"
#include "solver/modes/mode_factory.h"
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

void MainWindow::select_vertex(int vertex) { select_vertices(vertex >= 0 ? std::vector<int>{vertex} : std::vector<int>{}); }

void MainWindow::select_vertices(const std::vector<int>& vertices, bool add) {
  if (!add) {
    selection_.clear();
    selected_creases_.clear();
    picked_crease_point_ = -1;
  }
  for (int v : vertices)
    if (std::find(selection_.begin(), selection_.end(), v) == selection_.end()) selection_.push_back(v);
  selected_vertex_ = selection_.size() == 1 ? selection_.front() : -1;
  refresh_selection_marks();
  show_in_inspector(-1);
}

void MainWindow::select_creases(const std::vector<int>& creases, bool add) {
  if (!add) {
    selected_creases_.clear();
    selection_.clear();
    selected_vertex_ = -1;
  }
  const int count = model_ ? static_cast<int>(model_->fine.stitching.curves.size()) : 0;
  for (int k : creases)
    if (k >= 0 && k < count && std::find(selected_creases_.begin(), selected_creases_.end(), k) == selected_creases_.end())
      selected_creases_.push_back(k);
  refresh_selection_marks();
  show_in_inspector(-1);
}

void MainWindow::click(double x, double y) {
  if (!snapshot_) return;
  if (scene_->layer_on(vis::Layer::kCreaseCurves) && !model_->fine.stitching.curves.empty()) {
    const auto points = vis::crease_point_positions(model_->fine, shown_positions());
    Eigen::MatrixX3d rows(points.size(), 3);
    for (size_t p = 0; p < points.size(); ++p) rows.row(p) = points[p].transpose();
    const int point = pick_point(renderer_, rows, x, y, 8);
    const auto& curves = model_->fine.stitching.curves;
    for (int k = 0; point >= 0 && k < static_cast<int>(curves.size()); ++k) {
      if (std::find(curves[k].points.begin(), curves[k].points.end(), point) == curves[k].points.end()) continue;
      select_creases({k});
      picked_crease_point_ = point;
      status_->setText(QString("crease %1 picked at crease point %2 (Creases: Mountain, Valley, Angle..., Fold; "
                               "Edit > Add angle constraint: A)")
                           .arg(k)
                           .arg(point));
      return;
    }
  }
  const int v = pick_point(renderer_, shown_positions(), x, y, 12);
  select_vertex(v);
  status_->setText(v >= 0 ? QString("vertex %1 picked (Edit > Make handle: H)").arg(v)
                          : QString("no vertex within 12 pixels of the click"));
}

bool MainWindow::edit_creases(std::optional<Fold> fold, std::optional<double> angle) {
  if (selected_creases_.empty()) {
    report_error("Pick a crease first: switch the crease-curves overlay on (Ctrl+9) and click a crease.");
    return false;
  }
  const std::vector<int> creases = selected_creases_;
  post([creases, fold, angle](SolverWorker& w) { w.set_creases(creases, fold, angle); });
  const QString what = fold ? QString(enum_name(*fold)) : QString("%1 degrees").arg(*angle);
  status_->setText(QString("%1 crease(s) set to %2%3")
                       .arg(creases.size())
                       .arg(what)
                       .arg(config_.scenario == ScenarioKind::kFold
                                ? " - the fold goes on from the current shape (Creases > Fold starts again from flat)"
                                : " - Creases > Fold folds with the assignments"));
  return true;
}

void MainWindow::set_crease_fold(Fold fold) { edit_creases(fold, std::nullopt); }

void MainWindow::set_crease_angle(double degrees) {
  if (!(degrees >= 0 && degrees <= 180)) {
    report_error("A fold angle is from 0 to 180 degrees (its direction is the assignment's).");
    return;
  }
  edit_creases(std::nullopt, degrees);
}

void MainWindow::fold_creases() {
  if (!worker_) {
    report_error("Open a crease pattern first (File > Open pattern).");
    return;
  }
  chart_->clear();
  post([](SolverWorker& w) { w.fold(); });
  status_->setText("folding from the flat sheet with the crease assignments (Solver > Play: Space)");
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
  select_vertices(points_in_rectangle(renderer_, shown_positions(), x0, y0, x1, y1), add);
}

Eigen::MatrixX3d MainWindow::shown_positions() const {
  if (scene_options_.view == vis::View::kFlat) return model_->fine.V;
  return snapshot_->state.fine;
}

void MainWindow::refresh_selection_marks() {
  if (snapshot_)
    marks_->show_points(shown_positions(), selection_);
  else
    marks_->show_points(Eigen::MatrixX3d(0, 3), {});
  render();
}

void MainWindow::show_in_inspector(int hovered) {
  hovered_vertex_ = hovered;
  const int vertex = hovered >= 0 ? hovered : selected_vertex_;
  if (vertex < 0 && !selected_creases_.empty() && model_ && snapshot_) {
    attempt([&] {
      inspector_->setText("<i>picked</i><br>" + describe_creases(*model_, snapshot_->state.crease_folds,
                                                                 snapshot_->crease_angles, config_.fold_angle,
                                                                 selected_creases_));
    });
    return;
  }
  if (vertex < 0 || !model_ || !snapshot_) {
    inspector_->setText("Click a vertex to pick it, or point at one to inspect it.");
    return;
  }
  attempt([&] {
    inspector_->setText((hovered >= 0 ? QString("<i>under the mouse</i>") : QString("<i>picked</i>")) +
                        describe_vertex(*model_, snapshot_->state, vertex));
  });
}

}  // namespace sdog::studio
