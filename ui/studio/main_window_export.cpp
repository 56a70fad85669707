// MainWindow: pictures, surfaces, frame series and the mouse in the 3D view.
#include <QAction>
#include <QFileInfo>
#include <QPixmap>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkRenderWindowInteractor.h>

#include <cstdio>
#include <filesystem>

#include "base/atomic_output.h"
#include "base/errors.h"
#include "ui/studio/click_drag_style.h"
#include "ui/studio/main_window.h"
#include "ui/studio/screen_picking.h"
#include "ui/studio/selection_marks.h"
#include "ui/studio/solver_worker.h"
#include "geometry/trimmed_surface.h"
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

bool MainWindow::export_screenshot(const QString& path, const vis::ImageSize& size, bool transparent) {
  if (!snapshot_) {
    report_error("Nothing to export yet: open a crease pattern first (File > Open pattern).");
    return false;
  }
  vis::PictureOptions options;
  options.layers = scene_->layers_on();
  options.scene = scene_options_;
  options.scene.font_size = 0;
  options.size = size;
  options.transparent = transparent;
  options.camera = vis::camera_pose(renderer_->GetActiveCamera());
  return attempt([&] {
    write_file(path.toStdString(),
               [&](const std::string& tmp) { vis::render_picture(*model_, snapshot_->state, options, tmp); });
  });
}

bool MainWindow::export_surface(const QString& path) {
  if (!snapshot_) {
    report_error("Nothing to export yet: open a crease pattern first (File > Open pattern).");
    return false;
  }
  const std::string file = vis::with_surface_extension(path.toStdString(), vis::SurfaceFormat::Obj);
  const vis::SurfaceFormat format = vis::format_of_path(file).value_or(vis::SurfaceFormat::Obj);
  const vis::Layer colour = scene_->colour_layer().value_or(vis::Layer::Patches);
  const bool written = attempt([&] {
    const TrimmedSurface surface = trimmed_surface(model_->fine, snapshot_->state.fine);
    const MeshArrays arrays = vis::frame_arrays(*model_, snapshot_->state.fields);
    write_file(file, [&](const std::string& tmp) {
      vis::write_surface_file(format, surface, model_->fine, colour, arrays, tmp);
    });
  });
  if (written) status_->setText("trimmed surface written to " + QString::fromStdString(file));
  return written;
}

bool MainWindow::save_window_image(const QString& path) {
  render();
  const QPixmap picture = grab();
  return attempt([&] {
    write_file(path.toStdString(), [&](const std::string& tmp) {
      if (!picture.save(QString::fromStdString(tmp), "PNG"))
        throw OutputError("cannot write the window picture to " + path.toStdString());
    });
  });
}

bool MainWindow::start_frames(const QString& dir) {
  if (!worker_) {
    report_error("Open a crease pattern first (File > Open pattern).");
    return false;
  }
  stop_frames();
  if (!attempt([&] { png_frames_ = std::make_unique<OutputSet>(dir.toStdString()); })) return false;
  png_frame_count_ = 0;
  last_png_iteration_ = -1;
  const std::string d = dir.toStdString();
  post([d](SolverWorker& w) { w.start_frames(d); });
  if (frames_action_) frames_action_->setChecked(true);
  write_png_frame();
  return true;
}

void MainWindow::stop_frames() {
  if (!png_frames_) return;
  attempt([&] { png_frames_->commit(); });
  png_frames_.reset();
  if (frames_action_) frames_action_->setChecked(false);
  if (worker_) post([](SolverWorker& w) { w.stop_frames(); });
}

void MainWindow::write_png_frame() {
  // One picture per iteration shown (edits without an iteration add none).
  if (!snapshot_ || snapshot_->iteration == last_png_iteration_) return;
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", snapshot_->iteration);
  vis::PictureOptions options;
  options.layers = scene_->layers_on();
  options.scene = scene_options_;
  options.scene.font_size = 0;
  options.size = {std::max(64, view_->width()), std::max(64, view_->height())};
  options.camera = vis::camera_pose(renderer_->GetActiveCamera());
  if (!attempt([&] { vis::render_picture(*model_, snapshot_->state, options, png_frames_->temporary(name)); })) {
    png_frames_.reset();  // drops the frames written so far
    if (frames_action_) frames_action_->setChecked(false);
    return;
  }
  last_png_iteration_ = snapshot_->iteration;
  ++png_frame_count_;
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
  style->on_grab = [this](int x, int y) {
    if (!snapshot_ || snapshot_->constraints.handles.empty()) return false;
    const auto& handles = snapshot_->constraints.handles;
    Eigen::MatrixX3d targets(handles.size(), 3);
    for (size_t i = 0; i < handles.size(); ++i) targets.row(i) = handles[i].target.transpose();
    dragged_handle_ = pick_point(renderer_, targets, x, y, 15);
    if (dragged_handle_ < 0) return false;
    drag_depth_ = to_display(renderer_, handles[dragged_handle_].target).z();
    drag_moved_ = false;
    return true;
  };
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
