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
namespace {

// Grid lines (along the longer side) above which a new window shows no wireframe.
constexpr int kWireframeLines = 60;

// Whether the session changed between two of its snapshots (what a workspace would save).
bool changed(const Snapshot& a, const Snapshot& b) {
  if (a.iteration != b.iteration || a.mode != b.mode || a.scenario != b.scenario ||
      a.crease_settings.size() != b.crease_settings.size() || a.undo_name != b.undo_name ||
      a.constraints.handles.size() != b.constraints.handles.size() ||
      a.constraints.angles.size() != b.constraints.angles.size())
    return true;
  for (size_t k = 0; k < a.constraints.handles.size(); ++k)
    if (a.constraints.handles[k].target != b.constraints.handles[k].target) return true;
  return false;
}

// The model's warnings (model_warnings) for the status bar: " - warning: ..." each.
QString warnings_text(const DogModel& model) {
  QString text;
  for (const auto& w : model_warnings(model)) text += " - warning: " + QString::fromStdString(w);
  return text;
}

}  // namespace

QString with_extension(const QString& path, const QString& extension) {
  return QString::fromStdString(
      control::with_extension(path.toStdString(), extension.toStdString()));
}

MainWindow::MainWindow(const QString& about, QWidget* parent)
    : QMainWindow(parent),
      about_(about),
      render_window_(vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New()),
      renderer_(vtkSmartPointer<vtkRenderer>::New()) {
  qRegisterMetaType<sdog::studio::Snapshot>();
  qRegisterMetaType<sdog::IterationReport>();
  setWindowTitle("Scalable DOGs studio");
  setAcceptDrops(true);
  error_sink_ = [this](const QString& message) {
    QMessageBox::critical(this, "Scalable DOGs studio", message);
  };
  question_sink_ = [this](const QString& question, const QStringList& answers) {
    QMessageBox box(QMessageBox::Question, "Scalable DOGs studio", question, QMessageBox::NoButton,
                    this);
    std::vector<QPushButton*> buttons;
    for (int k = 0; k < answers.size(); ++k)
      buttons.push_back(box.addButton(
          answers[k], k + 1 == answers.size() ? QMessageBox::RejectRole : QMessageBox::AcceptRole));
    box.setDefaultButton(buttons.front());
    box.exec();
    const auto chosen = std::find(buttons.begin(), buttons.end(), box.clickedButton());
    return chosen == buttons.end() ? static_cast<int>(answers.size()) - 1
                                   : static_cast<int>(chosen - buttons.begin());
  };
  save_path_sink_ = [this](const QString& title, const QString& filter) {
    return QFileDialog::getSaveFileName(this, title, {}, filter);
  };

  view_ = new QVTKOpenGLNativeWidget(this);
  renderer_->SetBackground(1, 1, 1);
  render_window_->AddRenderer(renderer_);
  // No multisampling: with software OpenGL (Mesa's llvmpipe, as under xvfb) 8 samples per pixel
  // cost a third of the frame rate (sdog-studio --measure-fps); exported pictures have none either.
  // View > Smooth edges turns FXAA on instead.
  render_window_->SetMultiSamples(0);
  view_->setRenderWindow(render_window_);
  QString mouse_tip;
  for (const auto& [action, effect] : mouse_actions())
    mouse_tip += QString("%1%2: %3").arg(mouse_tip.isEmpty() ? "" : "\n", action, effect);
  view_->setToolTip(mouse_tip);
  view_->setMinimumSize(300, 240);
  setCentralWidget(view_);

  chart_ = new ObjectiveChart;
  auto* chart_dock = new QDockWidget("Iterations", this);
  chart_dock->setObjectName("iterations");
  chart_dock->setWidget(chart_);
  addDockWidget(Qt::RightDockWidgetArea, chart_dock);

  inspector_ = new QLabel("Click a vertex to pick it, or point at one to inspect it.");
  inspector_->setTextFormat(Qt::RichText);
  inspector_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  inspector_->setMargin(6);
  inspector_->setWordWrap(true);
  inspector_->setToolTip(
      "The picked fine vertex: patch, class, type and twin in the coarse mesh, residuals");
  auto* inspector_dock = new QDockWidget("Inspector", this);
  inspector_dock->setObjectName("inspector");
  inspector_dock->setWidget(inspector_);
  addDockWidget(Qt::RightDockWidgetArea, inspector_dock);

  status_ =
      new QLabel("Open a crease pattern (File > Open pattern, or drop an SVG or FOLD file here).");
  statusBar()->addWidget(status_, 1);
  recording_label_ = new QLabel;
  recording_label_->setStyleSheet("QLabel { color: #c00000; font-weight: bold; }");
  recording_label_->setToolTip("Recording frames (File > Record frames: uncheck to stop)");
  recording_label_->hide();
  statusBar()->addPermanentWidget(recording_label_);

  marks_ = std::make_unique<SelectionMarks>(renderer_);
  build_menus();
  wireframe_chosen_ = false;  // the menu's initial check is the default, not the user's choice
  build_solver_panel();
  set_up_mouse();
  update_actions();
  resize(1400, 900);
}

MainWindow::~MainWindow() {
  stop_worker();
  scene_.reset();  // before the renderer and the model it draws
  marks_.reset();
}

void MainWindow::report_error(const QString& message) {
  error_sink_(message);
}

bool MainWindow::attempt(const std::function<void()>& what) {
  try {
    what();
    return true;
  } catch (const std::exception& e) {
    report_error(QString::fromStdString(e.what()));
    return false;
  }
}

void MainWindow::post(std::function<void(SolverWorker&)> command) {
  if (!worker_) {
    report_error("Open a crease pattern first (File > Open pattern).");
    return;
  }
  worker_->post(std::move(command));
}

void MainWindow::stop_worker() {
  if (!worker_) return;
  QMetaObject::invokeMethod(
      worker_, [w = worker_] { w->pause(); }, Qt::BlockingQueuedConnection);
  solver_thread_.quit();
  solver_thread_.wait();
  delete worker_;
  worker_ = nullptr;
  playing_ = false;
  ++generation_;
}

void MainWindow::start_worker() {
  worker_ = new SolverWorker(model_);
  worker_->moveToThread(&solver_thread_);
  const int generation = ++generation_;
  connect(worker_, &SolverWorker::snapshot_ready, this, [this, generation](const Snapshot& s) {
    if (generation == generation_) show_snapshot(s);
  });
  connect(worker_, &SolverWorker::iterated, this, [this, generation](const IterationReport& r) {
    if (generation == generation_) show_report(r);
  });
  connect(worker_, &SolverWorker::failed, this, [this, generation](const QString& message) {
    if (generation == generation_) report_error(message);
  });
  connect(worker_, &SolverWorker::playing_changed, this, [this, generation](bool on) {
    if (generation != generation_) return;
    playing_ = on;
    update_actions();
  });
  connect(worker_, &SolverWorker::stopped_converged, this, [this, generation] {
    if (generation != generation_) return;
    status_->setText(status_->text() +
                     " - done: the targets no longer move and the shape has converged "
                     "(edit a constraint or press Play to go on)");
    if (snapshot_) chart_->add_mark(snapshot_->iteration, "done");
  });
  connect(worker_, &SolverWorker::workspace_saved, this, [this](const QString& path) {
    modified_ = false;
    status_->setText("workspace saved to " + QFileInfo(path).absoluteFilePath());
    Q_EMIT workspace_saved(path);
  });
  solver_thread_.start();
}

bool MainWindow::open_pattern(const QString& path, const QString& resolution, const QString& mode) {
  std::shared_ptr<const DogModel> model;
  const std::string mode_name = mode.toStdString();
  const bool built = attempt([&] {
    const ModeKind kind = parse_enum<ModeKind>(mode_name, "mode: ");
    model = load_model(path.toStdString(), resolution.toStdString());
    check_mode_usable(kind, *model);
  });
  if (!built) return false;
  show_model(std::move(model), path, mode_name, std::nullopt);
  return true;
}

void MainWindow::show_model(std::shared_ptr<const DogModel> model, const QString& path,
                            const std::string& mode_name, const std::optional<Workspace>& state) {
  stop_frames();
  stop_worker();
  scene_.reset();
  snapshot_.reset();
  chart_->clear();
  reports_received_ = 0;
  modified_ = false;
  selection_.clear();
  refresh_selection_marks();
  show_in_inspector(-1);
  // A run configuration names vertices, crease points and creases of its pattern: another pattern
  // does not get it.
  QString dropped;
  if (!config_pattern_.isEmpty() &&
      QFileInfo(config_pattern_).absoluteFilePath() != QFileInfo(path).absoluteFilePath()) {
    if (!config_file_.isEmpty()) {
      dropped =
          QString(" - the run configuration of %1 (for %2) is dropped: default solver settings")
              .arg(QFileInfo(config_file_).fileName(), QFileInfo(config_pattern_).fileName());
      config_ = RunConfig{};
    } else if (!config_.creases.empty()) {
      dropped = QString(" - the crease assignments set for %1 are dropped")
                    .arg(QFileInfo(config_pattern_).fileName());
      config_.creases.clear();
    }
    config_file_.clear();
  }
  config_pattern_ = path;
  model_ = std::move(model);
  pattern_path_ = path;
  resolution_ = QString::fromStdString(
      Resolution{model_->fine.nx(), model_->fine.ny()}.str());  // "auto" resolved
  mode_ = mode_name;
  scene_ = std::make_unique<vis::Scene>(*model_, renderer_, scene_options_);
  if (!wireframe_chosen_) {  // from about 60 grid lines on, the quad edges hide the surface
    const QSignalBlocker block(layer_actions_.at(vis::Layer::kWireframe));
    layer_actions_.at(vis::Layer::kWireframe)
        ->setChecked(std::max(model_->fine.nx(), model_->fine.ny()) <= kWireframeLines);
  }
  for (const auto& [layer, action] : layer_actions_) scene_->set_layer(layer, action->isChecked());
  camera_fitted_ = false;
  start_worker();
  const RunConfig config = config_;
  post([config, mode_name, state](SolverWorker& w) { w.open(config, mode_name, state); });
  setWindowTitle(QFileInfo(path).fileName() + " " + resolution_ + " - Scalable DOGs studio");
  status_->setText(
      QString(
          "%1 at %2: %3 fine vertices in %4 patches, %5; mode %6, scenario %7 (Solver > Step: S, "
          "Play: Space)")
          .arg(QFileInfo(path).fileName(), resolution_)
          .arg(model_->fine.vertex_count())
          .arg(model_->fine.patch_count())
          .arg(model_->has_coarse
                   ? QString("coarse mesh %1 vertices").arg(model_->coarse.vertex_count())
                   : QString("no coarse mesh (even resolution)"))
          .arg(QString::fromStdString(mode_), QString(enum_name(config_.scenario))) +
      dropped + warnings_text(*model_));
  update_actions();
  show_solver_state();
  render();
}

bool MainWindow::change_resolution(const QString& resolution) {
  if (!model_) {
    report_error("Open a crease pattern first (File > Open pattern).");
    return false;
  }
  return open_pattern(pattern_path_, resolution, QString::fromStdString(mode_));
}

void MainWindow::show_snapshot(const Snapshot& s) {
  const bool updated = attempt([&] { scene_->update(s.state); });
  if (updated) {
    if (snapshot_) {
      if (changed(*snapshot_, s)) modified_ = true;
      if (snapshot_->mode != s.mode)
        chart_->add_mark(s.iteration, "mode " + QString::fromStdString(s.mode));
    }
    if (!s.scenario_done) scenario_end_marked_ = false;
    snapshot_ = s;
    // The session's crease edits and Creases > Fold change its configuration: the next session
    // (another scenario, new settings) starts with them.
    config_.creases = s.crease_settings;
    if (mode_ != s.mode || config_.scenario != s.scenario) {
      mode_ = s.mode;
      config_.scenario = s.scenario;
      show_solver_state();
    }
    if (!camera_fitted_) {
      scene_->reset_camera();
      if (pending_camera_) {
        attempt([&] {
          vis::apply_camera_pose(vis::camera_pose_from_json(*pending_camera_, "workspace camera"),
                                 renderer_->GetActiveCamera());
        });
        pending_camera_.reset();
      }
      camera_fitted_ = true;
    } else if (keep_framed_) {
      scene_->frame_all();
    }
    refresh_selection_marks();  // renders
    record_frame();
    show_in_inspector(hovered_vertex_);
  }
  if (worker_) worker_->acknowledge();
  update_actions();
  Q_EMIT snapshot_shown();
}

void MainWindow::show_report(const IterationReport& r) {
  ++reports_received_;
  chart_->add(r);
  if (snapshot_ && !snapshot_->scenario_done && r.t >= 1 && !scenario_end_marked_) {
    chart_->add_mark(r.iteration, "scenario end");
    scenario_end_marked_ = true;
  }
  QString progress;
  if (r.step.stage == settling_stage::kRunning) {
    progress = ", settling (folding straight from the start state to compare)";
  } else if (r.step.stage == settling_stage::kReplaced) {
    progress =
        ", converged (settled: the fold straight from the start state is lower and replaces it)";
  } else if (r.step.converged) {
    progress = *r.step.converged ? ", converged"
                                 : QString(", converging (%1% of the targets' move)")
                                       .arg(100 * r.step.target_fraction, 0, 'f', 0);
  }
  status_->setText(
      QString("iteration %1 (%2, t = %3): objective %4, DOG residual max %5, stitch gap max %6, "
              "%7 ms%8%9")
          .arg(r.iteration)
          .arg(QString::fromStdString(r.mode))
          .arg(r.t, 0, 'f', 3)
          .arg(r.diagnostics.objective, 0, 'g', 4)
          .arg(r.diagnostics.dog_max, 0, 'g', 3)
          .arg(r.diagnostics.stitch_gap_max, 0, 'g', 3)
          .arg(r.iteration_ms, 0, 'f', 1)
          .arg(progress)
          .arg(r.step.failed ? ", FAILED: " + QString::fromStdString(r.step.failure) : QString()));
}

void MainWindow::render() {
  if (scene_) scene_->layout_legends();
  render_window_->Render();
  view_->update();
}

QString MainWindow::inspector_text() const {
  return inspector_->text();
}
QString MainWindow::status_text() const {
  return status_->text();
}

bool MainWindow::open_workspace(const QString& path) {
  Workspace w;
  std::shared_ptr<const DogModel> model;
  if (!attempt([&] {
        w = load_workspace(path.toStdString());
        model = load_model(w.pattern, w.resolution);
      }))
    return false;
  return open_state(std::move(model), w, path);
}

bool MainWindow::open_state(std::shared_ptr<const DogModel> model, const Workspace& state,
                            const QString& source) {
  if (!attempt([&] { check_mode_usable(parse_enum<ModeKind>(state.mode, "mode: "), *model); }))
    return false;
  const QString pattern = QString::fromStdString(state.pattern);
  config_ = state.config;
  config_file_ = source;
  config_pattern_ = pattern;
  if (!state.camera.is_null()) pending_camera_ = state.camera;
  show_model(std::move(model), pattern, state.mode, state);
  return true;
}

bool MainWindow::save_workspace(const QString& path) {
  if (!worker_) {
    report_error("Open a crease pattern first (File > Open pattern).");
    return false;
  }
  const std::string file = with_extension(path, "json").toStdString(),
                    pattern = QFileInfo(pattern_path_).absoluteFilePath().toStdString(),
                    res = resolution_.toStdString();
  const nlohmann::json camera = camera_json();
  post([file, pattern, res, camera](SolverWorker& w) {
    w.save_workspace(file, pattern, res, camera);
  });
  return true;
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const auto urls = event->mimeData()->urls();
  if (urls.isEmpty()) return;
  open_file(urls.front().toLocalFile());
  event->acceptProposedAction();
}

void MainWindow::open_file(const QString& path) {
  if (!settle_unsaved("opening " + QFileInfo(path).fileName())) return;
  if (path.endsWith(".json", Qt::CaseInsensitive))
    open_workspace(path);
  else if (path.endsWith(".svg", Qt::CaseInsensitive) ||
           path.endsWith(".fold", Qt::CaseInsensitive))
    open_pattern(path, resolution_.isEmpty() ? QString("auto") : resolution_,
                 QString::fromStdString(mode_));
  else
    report_error("Cannot open " + path +
                 ": the studio opens crease patterns (.svg, .fold) and workspaces (.json).");
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!settle_unsaved("closing")) {
    event->ignore();
    return;
  }
  stop_frames();
  stop_worker();
  event->accept();
}

}  // namespace sdog::studio
