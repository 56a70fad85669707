// MainWindow: pictures, surfaces, frame series and the mouse in the 3D view.
#include <QAction>
#include <QFileInfo>
#include <QLabel>
#include <QPixmap>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkRenderWindowInteractor.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "base/atomic_output.h"
#include "base/errors.h"
#include "ui/studio/click_drag_style.h"
#include "ui/studio/main_window.h"
#include "ui/studio/screen_picking.h"
#include "ui/studio/selection_marks.h"
#include "ui/studio/solver_worker.h"
#include "geometry/surface/trimmed_surface.h"
#include "ui/vis/camera.h"
#include "ui/vis/frame_writer.h"
#include "ui/vis/picture.h"
#include "ui/vis/surface_files.h"

namespace sdog::studio {
namespace {

/// Calls write(temporary path) and gives the file its name only when that succeeded.
void write_file(const std::string& path, const std::function<void(const std::string&)>& write) {
  const std::filesystem::path target(path);
  OutputSet out(target.has_parent_path() ? target.parent_path().string() : ".");
  write(out.temporary(target.filename().string()));
  out.commit();
}

}  // namespace

bool MainWindow::export_screenshot(const QString& path, const vis::ImageSize& size, bool transparent, bool frame) {
  if (!snapshot_) {
    report_error("Nothing to export yet: open a crease pattern first (File > Open pattern).");
    return false;
  }
  const QString file = with_extension(path, "png");
  vis::PictureOptions options = picture_options({size.width, size.height});
  options.transparent = transparent;
  options.frame = frame;
  const bool written = attempt([&] {
    write_file(file.toStdString(),
               [&](const std::string& tmp) { vis::render_picture(*model_, snapshot_->state, options, tmp); });
  });
  if (written)
    status_->setText(QString("screenshot (%1x%2) written to %3")
                         .arg(size.width)
                         .arg(size.height)
                         .arg(QFileInfo(file).absoluteFilePath()));
  return written;
}

bool MainWindow::export_surface(const QString& path) {
  if (!snapshot_) {
    report_error("Nothing to export yet: open a crease pattern first (File > Open pattern).");
    return false;
  }
  const std::string file = vis::with_surface_extension(path.toStdString(), vis::SurfaceFormat::kObj);
  const vis::SurfaceFormat format = vis::format_of_path(file).value_or(vis::SurfaceFormat::kObj);
  const vis::Layer colour = scene_->colour_layer().value_or(vis::Layer::kPatches);
  const bool written = attempt([&] {
    const TrimmedSurface surface = trimmed_surface(model_->fine, snapshot_->state.fine);
    const MeshArrays arrays = vis::frame_arrays(*model_, snapshot_->state.fields);
    write_file(file, [&](const std::string& tmp) {
      vis::write_surface_file(format, surface, model_->fine, colour, arrays, tmp);
    });
  });
  if (written) status_->setText("trimmed surface written to " + QFileInfo(QString::fromStdString(file)).absoluteFilePath());
  return written;
}

bool MainWindow::save_window_image(const QString& path, bool frame_sheet) {
  if (frame_sheet) frame_all();
  render();
  const QPixmap picture = grab();
  return attempt([&] {
    write_file(path.toStdString(), [&](const std::string& tmp) {
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

bool MainWindow::start_frames(const QString& dir, const RecordingOptions& options, bool frame) {
  if (!worker_ || !snapshot_) {
    report_error("Open a crease pattern first (File > Open pattern).");
    return false;
  }
  stop_frames();
  if (!attempt([&] { recorder_ = std::make_unique<Recorder>(*model_, dir.toStdString(), options); })) return false;
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
  status_->setText(QString("recording stopped: %1 frames (%2 MB) in %3 (frames.csv lists their iterations)")
                       .arg(recorder->frame_count())
                       .arg(recorder->bytes() / 1e6, 0, 'f', 1)
                       .arg(dir));
  Q_EMIT frames_written(dir, recorder->frame_count());
}

int MainWindow::frames_recorded() const { return recorder_ ? recorder_->frame_count() : 0; }

QString MainWindow::recording_indicator() const { return recording_label_->isVisible() ? recording_label_->text() : QString(); }

void MainWindow::update_recording_indicator() {
  if (!recorder_) {
    recording_label_->hide();
    return;
  }
  recording_label_->setText(QString("\u25CF REC %1 frames, %2 MB").arg(recorder_->frame_count()).arg(recorder_->bytes() / 1e6, 0, 'f', 1));
  recording_label_->show();
}

void MainWindow::record_frame() {
  if (!recorder_ || !snapshot_ || !recorder_->due(snapshot_->iteration)) return;
  vis::PictureOptions options =
      picture_options({std::max(64, view_->width() / 2 * 2), std::max(64, view_->height() / 2 * 2)});
  options.frame = record_framed_;
  if (!attempt([&] { recorder_->record(snapshot_->state, snapshot_->iteration, snapshot_->time, options); })) {
    stop_frames();  // the frames written so far stay
    return;
  }
  update_recording_indicator();
}

bool MainWindow::grab_target(double x, double y) {
  if (!snapshot_ || !scene_ || !scene_->layer_on(vis::Layer::kHandles)) return false;
  const auto& drawn = snapshot_->state.constraints.handles;  // the scenario's and the user's
  if (drawn.empty()) return false;
  Eigen::MatrixX3d targets(drawn.size(), 3);
  for (size_t i = 0; i < drawn.size(); ++i) targets.row(i) = drawn[i].target.transpose();
  const int picked = pick_point(renderer_, targets, x, y, 15);
  if (picked < 0) return false;
  const auto& handles = snapshot_->constraints.handles;
  const auto user = std::find_if(handles.begin(), handles.end(),
                                 [&](const UserConstraints::Handle& h) { return h.vertex == drawn[picked].vertex; });
  drag_depth_ = to_display(renderer_, drawn[picked].target).z();
  if (user != handles.end()) {
    dragged_handle_ = static_cast<int>(user - handles.begin());
    drag_moved_ = false;
  } else {  // a target of the scenario: a handle takes it over, and the drag continues that edit
    const int vertex = drawn[picked].vertex;
    const Eigen::Vector3d target = drawn[picked].target;
    post([vertex, target](SolverWorker& w) { w.add_handle_at(vertex, target); });
    dragged_handle_ = static_cast<int>(handles.size());
    drag_moved_ = true;
    status_->setText(QString("the scenario's target of vertex %1 is now a handle (Edit > Undo takes it back)").arg(vertex));
  }
  return true;
}

vtkRenderWindowInteractor* MainWindow::interactor() const { return view_->interactor(); }

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
    status_->setText(QString("%1 vertices selected (Edit > Make handle: H)").arg(selection_.size()));
  };
  style->on_grab = [this](int x, int y) { return grab_target(x, y); };
  // The target follows the mouse while the button is down; the solver gets the newest target
  // whenever it is ready for one (SolverWorker::drag_handle), and the whole drag is one edit.
  auto drag_to = [this](int x, int y) {
    if (dragged_handle_ < 0 || !worker_) return;
    const Eigen::Vector3d p = to_world(renderer_, x, y, drag_depth_);
    worker_->drag_handle(dragged_handle_, p, /*first=*/!drag_moved_);
    drag_moved_ = true;
    status_->setText(QString("handle %1 at (%2, %3, %4)")
                         .arg(dragged_handle_)
                         .arg(p.x(), 0, 'f', 2)
                         .arg(p.y(), 0, 'f', 2)
                         .arg(p.z(), 0, 'f', 2));
  };
  style->on_drag = drag_to;
  style->on_release = [this, drag_to](int x, int y) {
    drag_to(x, y);
    dragged_handle_ = -1;
  };
  view_->interactor()->SetInteractorStyle(style);
}

}  // namespace sdog::studio
