// MainWindow: overlays, views, the camera and camera files.
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

void MainWindow::set_layer(vis::Layer layer, bool on) {
  if (layer == vis::Layer::kWireframe) wireframe_chosen_ = true;
  QAction* action = layer_actions_.at(layer);
  if (action->isChecked() != on) action->setChecked(on);  // toggled() applies it
  if (!scene_) return;
  scene_->set_layer(layer, on);
  // A colour layer switched on turns the other one off: the actions follow the scene.
  for (const auto& [l, a] : layer_actions_) {
    const QSignalBlocker block(a);
    a->setChecked(scene_->layer_on(l));
  }
  render();
}

void MainWindow::set_view(vis::View view) {
  scene_options_.view = view;
  view_actions_.at(view)->setChecked(true);
  if (!scene_) return;
  scene_->set_options(scene_options_);
  scene_->reset_camera();
  refresh_selection_marks();
}

void MainWindow::set_coarse_visible(bool on) {
  scene_options_.coarse = on;
  if (coarse_action_->isChecked() != on) coarse_action_->setChecked(on);
  if (!scene_) return;
  scene_->set_options(scene_options_);
  render();
}

void MainWindow::set_smooth_edges(bool on) {
  renderer_->SetUseFXAA(on);
  if (smooth_action_->isChecked() != on) smooth_action_->setChecked(on);
  render();
}

void MainWindow::reset_camera() {
  if (!scene_) return;
  scene_->reset_camera();
  render();
}

void MainWindow::frame_all() {
  if (!scene_) return;
  scene_->frame_all();
  render();
}

void MainWindow::set_keep_framed(bool on) {
  keep_framed_ = on;
  if (keep_framed_action_ && keep_framed_action_->isChecked() != on)
    keep_framed_action_->setChecked(on);
  if (on) frame_all();
}

nlohmann::json MainWindow::camera_json() const {
  return vis::to_json(vis::camera_pose(renderer_->GetActiveCamera()));
}

bool MainWindow::save_camera(const QString& path) {
  const QString file = with_extension(path, "json");
  const bool saved = attempt([&] {
    vis::save_camera(vis::camera_pose(renderer_->GetActiveCamera()), file.toStdString());
  });
  if (saved) status_->setText("camera saved to " + QFileInfo(file).absoluteFilePath());
  return saved;
}

bool MainWindow::load_camera(const QString& path) {
  const bool ok = attempt([&] {
    vis::apply_camera_pose(vis::load_camera(path.toStdString()), renderer_->GetActiveCamera());
  });
  if (ok) render();
  return ok;
}

}  // namespace sdog::studio
