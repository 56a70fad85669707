// MainWindow: pictures, surfaces, frame series and the mouse in the 3D view.
#include <QVTKOpenGLNativeWidget.h>
#include <vtkRenderWindowInteractor.h>
#include <QAction>
#include <QFileInfo>
#include <QLabel>
#include <QPixmap>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "base/atomic_output.h"
#include "base/errors.h"
#include "geometry/surface/trimmed_surface.h"
#include "ui/control/exports.h"
#include "ui/control/handle_drag.h"
#include "ui/studio/click_drag_style.h"
#include "ui/studio/main_window.h"
#include "ui/studio/screen_picking.h"
#include "ui/studio/selection_marks.h"
#include "ui/studio/solver_worker.h"
#include "ui/vis/camera.h"
#include "ui/vis/frame_writer.h"
#include "ui/vis/picture.h"
#include "ui/vis/surface_files.h"

namespace sdog::studio {

bool MainWindow::export_screenshot(const QString& path, const vis::ImageSize& size,
                                   bool transparent, bool frame) {
  if (!snapshot_) {
    report_error("Nothing to export yet: open a crease pattern first (File > Open pattern).");
    return false;
  }
  vis::PictureOptions options = picture_options({size.width, size.height});
  options.transparent = transparent;
  options.frame = frame;
  std::string file;
  const bool written = attempt([&] {
    file = control::export_picture(*model_, snapshot_->state, options, path.toStdString());
  });
  if (written)
    status_->setText(QString("screenshot (%1x%2) written to %3")
                         .arg(size.width)
                         .arg(size.height)
                         .arg(QFileInfo(QString::fromStdString(file)).absoluteFilePath()));
  return written;
}

bool MainWindow::export_surface(const QString& path) {
  if (!snapshot_) {
    report_error("Nothing to export yet: open a crease pattern first (File > Open pattern).");
    return false;
  }
  const vis::Layer colour = scene_->colour_layer().value_or(vis::Layer::kPatches);
  std::string file;
  const bool written = attempt([&] {
    file = control::export_surface(*model_, snapshot_->state, colour, path.toStdString());
  });
  if (written)
    status_->setText("trimmed surface written to " +
                     QFileInfo(QString::fromStdString(file)).absoluteFilePath());
  return written;
}

bool MainWindow::save_window_image(const QString& path, bool frame_sheet) {
  if (frame_sheet) frame_all();
  render();
  const QPixmap picture = grab();
  return attempt([&] {
    control::write_whole_file(path.toStdString(), [&](const std::string& tmp) {
      if (!picture.save(QString::fromStdString(tmp), "PNG"))
        throw OutputError("cannot write the window picture to " + path.toStdString());
    });
  });
}

vis::PictureOptions MainWindow::picture_options(const vis::ImageSize& size) const {
  vis::PictureOptions options;
  options.layers = scene_->layers_on();
  options.scene = scene_options_;
  options.scene.font_size = 0;
  options.size = size;
  options.camera = vis::camera_pose(renderer_->GetActiveCamera());
  return options;
}

bool MainWindow::start_frames(const QString& dir, const control::RecordingOptions& options,
                              bool frame) {
  if (!worker_ || !snapshot_) {
    report_error("Open a crease pattern first (File > Open pattern).");
    return false;
  }
  stop_frames();
  if (!attempt([&] {
        recorder_ = std::make_unique<control::Recorder>(*model_, dir.toStdString(), options);
      }))
    return false;
  record_framed_ = frame;
  const int every = options.every;
  post([every](SolverWorker& w) { w.set_recording(every); });
  if (frames_action_) frames_action_->setChecked(true);
  record_frame();  // the state shown now is frame 0
  update_recording_indicator();
  return recorder_ != nullptr;
}

void MainWindow::stop_frames() {
  if (!recorder_) return;
  const auto recorder = std::move(recorder_);
  if (frames_action_) frames_action_->setChecked(false);
  if (worker_) post([](SolverWorker& w) { w.set_recording(0); });
  update_recording_indicator();
  const QString dir = QFileInfo(QString::fromStdString(recorder->dir())).absoluteFilePath();
  status_->setText(
      QString::fromStdString(control::recording_summary(*recorder, dir.toStdString())));
  Q_EMIT frames_written(dir, recorder->frame_count());
}

int MainWindow::frames_recorded() const {
  return recorder_ ? recorder_->frame_count() : 0;
}

QString MainWindow::recording_indicator() const {
  return recording_label_->isVisible() ? recording_label_->text() : QString();
}

void MainWindow::update_recording_indicator() {
  if (!recorder_) {
    recording_label_->hide();
    return;
  }
  recording_label_->setText(QString::fromStdString(control::recording_indicator(*recorder_)));
  recording_label_->show();
}

void MainWindow::record_frame() {
  if (!recorder_ || !snapshot_ || !recorder_->due(snapshot_->iteration)) return;
  vis::PictureOptions options = picture_options(
      {std::max(64, view_->width() / 2 * 2), std::max(64, view_->height() / 2 * 2)});
  options.frame = record_framed_;
  if (!attempt([&] {
        recorder_->record(snapshot_->state, snapshot_->iteration, snapshot_->time, options);
      })) {
    stop_frames();  // the frames written so far stay
    return;
  }
  update_recording_indicator();
}

bool MainWindow::grab_target(double x, double y) {
  if (!snapshot_ || !scene_ || !scene_->layer_on(vis::Layer::kHandles)) return false;
  const auto& drawn = snapshot_->state.constraints;  // the scenario's handles and the user's
  Eigen::MatrixX3d targets(drawn.handles.size(), 3);
  for (size_t i = 0; i < drawn.handles.size(); ++i)
    targets.row(i) = drawn.handles[i].target.transpose();
  const auto grab = control::grab_target(drawn, project_to_display(renderer_, targets),
                                         snapshot_->constraints, x, y);
  if (!grab) return false;
  drag_.begin(*grab);
  if (grab->new_handle) {  // a target of the scenario: a handle takes it over, and the drag
                           // continues that edit
    const int vertex = grab->vertex;
    const Eigen::Vector3d target = grab->target;
    post([vertex, target](SolverWorker& w) { w.add_handle_at(vertex, target); });
    status_->setText(
        QString("the scenario's target of vertex %1 is now a handle (Edit > Undo takes it back)")
            .arg(vertex));
  }
  return true;
}

vtkRenderWindowInteractor* MainWindow::interactor() const {
  return view_->interactor();
}

void MainWindow::set_up_mouse() {
  vtkNew<ClickDragStyle> style;
  style->on_click = [this](int x, int y) { click(x, y); };
  style->on_hover = [this](int x, int y) {
    if (!snapshot_) return;
    show_in_inspector(pick_point(renderer_, shown_positions(), x, y, 12));
  };
  style->on_band = [this](int x0, int y0, int x, int y) {
    marks_->show_band(x0, y0, x, y);
    render();
  };
  style->on_band_end = [this](int x0, int y0, int x1, int y1, bool add) {
    marks_->hide_band();
    select_in_rectangle(x0, y0, x1, y1, add);  // renders
    status_->setText(
        QString("%1 vertices selected (Edit > Make handle: H)").arg(selection_.vertices().size()));
  };
  style->on_grab = [this](int x, int y) { return grab_target(x, y); };
  // The target follows the mouse while the button is down; the solver gets the newest target
  // whenever it is ready for one (SolverWorker::drag_handle), and the whole drag is one edit.
  auto drag_to = [this](int x, int y) {
    if (!drag_.active() || !worker_) return;
    const Eigen::Vector3d p = to_world(renderer_, x, y, drag_.depth());
    worker_->drag_handle(drag_.handle(), p, /*first=*/drag_.move());
    status_->setText(QString::fromStdString(drag_.describe(p)));
  };
  style->on_drag = drag_to;
  style->on_release = [this, drag_to](int x, int y) {
    drag_to(x, y);
    drag_.end();
  };
  view_->interactor()->SetInteractorStyle(style);
}

}  // namespace sdog::studio
