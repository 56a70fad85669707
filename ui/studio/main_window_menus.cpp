// MainWindow: the menus, their shortcuts and the dialogs behind them.
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFileDialog>
#include <QInputDialog>
#include <QKeySequence>
#include <QMenuBar>
#include <QMessageBox>
#include <cmath>

#include "solver/modes/mode_kind.h"
#include "ui/studio/click_drag_style.h"
#include "ui/studio/export_dialog.h"
#include "ui/studio/main_window.h"
#include "ui/studio/objective_chart.h"
#include "ui/studio/record_dialog.h"
#include "ui/studio/solver_panel.h"
#include "ui/studio/solver_settings.h"
#include "ui/vis/surface_files.h"

namespace sdog::studio {
namespace {

QAction* add_action(QMenu* menu, const QString& text, const QKeySequence& keys,
                    const QString& tip) {
  QAction* a = menu->addAction(text);
  a->setShortcut(keys);
  a->setToolTip(tip);
  a->setStatusTip(tip);
  return a;
}

/// Index of the constraint the user chooses from `items`; -1 when cancelled or there is none (said
/// in a message).
int choose(QWidget* parent, const QString& title, const QStringList& items) {
  if (items.isEmpty()) {
    QMessageBox::information(parent, title, "There is no such constraint to remove.");
    return -1;
  }
  bool ok = false;
  const QString item = QInputDialog::getItem(parent, title, "Constraint:", items, 0, false, &ok);
  return ok ? static_cast<int>(items.indexOf(item)) : -1;
}

}  // namespace

void MainWindow::build_menus() {
  build_file_menu();
  build_edit_menu();
  build_view_menu();
  build_crease_menu();
  build_solver_menu();
  build_help_menu();
  for (QMenu* menu : menuBar()->findChildren<QMenu*>()) menu->setToolTipsVisible(true);
}

// File > Export screenshot, Export surface and Record frames.
void MainWindow::add_export_actions(QMenu* m) {
  connect(add_action(m, "Export &screenshot...", QKeySequence("Ctrl+E"),
                     "Render the view to PNG: file, size, transparent background, and the sheet "
                     "framed to fill "
                     "the picture or the view's camera as it is"),
          &QAction::triggered, this, [this] {
            ExportDialog dialog(last_screenshot_, last_screenshot_size_, this);
            if (dialog.exec() != QDialog::Accepted) return;
            if (dialog.path().isEmpty()) {
              report_error("No file named for the screenshot.");
              return;
            }
            last_screenshot_ = dialog.path();
            last_screenshot_size_ = dialog.size();
            export_screenshot(dialog.path(), dialog.size(), dialog.transparent(), dialog.frame());
          });
  connect(
      add_action(
          m, "Export sur&face...", QKeySequence("Ctrl+Shift+E"),
          "Write the trimmed surface of the current state as OBJ or PLY (sheet units, normals; PLY "
          "coloured by the colour overlay that is on)"),
      &QAction::triggered, this, [this] {
        QString filter;
        const QString path = QFileDialog::getSaveFileName(
            this, "Export surface", {}, "OBJ files (*.obj);;PLY files (*.ply)", &filter);
        if (path.isEmpty()) return;
        // Without an extension of its own the path takes the chosen filter's.
        const auto format =
            filter.contains("*.ply") ? vis::SurfaceFormat::kPly : vis::SurfaceFormat::kObj;
        export_surface(
            QString::fromStdString(vis::with_surface_extension(path.toStdString(), format)));
      });
  frames_action_ = add_action(
      m, "Record &frames...", QKeySequence("Ctrl+Shift+F"),
      "Write states as they are shown into a folder, numbered from frame_0000: pictures, "
      ".vtu meshes and/or trimmed surfaces, every N iterations; uncheck to stop");
  frames_action_->setCheckable(true);
  connect(frames_action_, &QAction::triggered, this, [this](bool on) {
    if (!on) {
      stop_frames();
      return;
    }
    frames_action_->setChecked(false);
    RecordDialog dialog(last_recording_dir_, this);
    if (dialog.exec() != QDialog::Accepted) return;
    if (dialog.dir().isEmpty()) {
      report_error("No folder named for the frames.");
      return;
    }
    last_recording_dir_ = dialog.dir();
    start_frames(dialog.dir(), dialog.options(), dialog.frame());
  });
}

void MainWindow::build_file_menu() {
  QMenu* m = menuBar()->addMenu("&File");
  connect(add_action(m, "&Open pattern...", QKeySequence::Open,
                     "Mesh a crease pattern (SVG or FOLD) at a resolution"),
          &QAction::triggered, this, [this] {
            if (!settle_unsaved("opening another pattern")) return;
            const QString path = QFileDialog::getOpenFileName(this, "Open crease pattern", {},
                                                              "Crease patterns (*.svg *.fold)");
            if (path.isEmpty()) return;
            bool ok = false;
            const QString res = QInputDialog::getText(
                this, "Resolution",
                "Grid lines XxY (odd values also build the coarse mesh), or auto (41 along the "
                "longer side):",
                QLineEdit::Normal, resolution_.isEmpty() ? "auto" : resolution_, &ok);
            if (ok) open_pattern(path, res, QString::fromStdString(mode_));
          });
  connect(
      add_action(
          m, "Change &resolution...", QKeySequence("Ctrl+R"),
          "Mesh the open pattern again at another resolution (odd values for the coarse modes)"),
      &QAction::triggered, this, [this] {
        if (!settle_unsaved("meshing the pattern again")) return;
        bool ok = false;
        const QString res = QInputDialog::getText(
            this, "Resolution", "Grid lines XxY, or auto:", QLineEdit::Normal, resolution_, &ok);
        if (ok) change_resolution(res);
      });
  m->addSeparator();
  connect(add_action(m, "Open &workspace...", QKeySequence("Ctrl+Shift+O"),
                     "Open a saved workspace: pattern, resolution, mode, settings, constraints, "
                     "camera, positions"),
          &QAction::triggered, this, [this] {
            if (!settle_unsaved("opening a workspace")) return;
            const QString path =
                QFileDialog::getOpenFileName(this, "Open workspace", {}, "Workspaces (*.json)");
            if (!path.isEmpty()) open_workspace(path);
          });
  connect(add_action(m, "&Save workspace...", QKeySequence::Save,
                     "Save the session as a workspace (JSON)"),
          &QAction::triggered, this, [this] {
            const QString path = save_path_sink_("Save workspace", "Workspaces (*.json)");
            if (!path.isEmpty()) save_workspace(path);
          });
  m->addSeparator();
  add_export_actions(m);
  m->addSeparator();
  connect(add_action(m, "&Quit", QKeySequence::Quit, "Close the studio"), &QAction::triggered, this,
          &QWidget::close);
}

void MainWindow::build_edit_menu() {
  QMenu* m = menuBar()->addMenu("&Edit");
  undo_action_ = add_action(m, "&Undo", QKeySequence::Undo,
                            "Undo the last edit (a constraint, a crease assignment or angle)");
  connect(undo_action_, &QAction::triggered, this, &MainWindow::undo);
  redo_action_ = add_action(m, "&Redo", QKeySequence("Ctrl+Shift+Z"), "Redo the edit undone last");
  connect(redo_action_, &QAction::triggered, this, &MainWindow::redo);
  m->addSeparator();
  connect(add_action(m, "Make &handle", QKeySequence("H"),
                     "Hold the selected vertices (click one, or Ctrl + drag a rubber band around "
                     "several) where "
                     "they are; Shift + drag a handle to move it"),
          &QAction::triggered, this, [this] {
            if (selection_.vertices().empty())
              report_error(
                  "Select vertices first: click one in the view, or Ctrl + drag a rubber band "
                  "around several.");
            else
              add_handles(selection_.vertices());
          });
  connect(add_action(m, "Remove handle...", QKeySequence("Shift+H"),
                     "Remove one of the position handles"),
          &QAction::triggered, this, [this] {
            QStringList items;
            if (snapshot_)
              for (const auto& h : snapshot_->constraints.handles)
                items << QString("vertex %1").arg(h.vertex);
            if (const int i = choose(this, "Remove handle", items); i >= 0) remove_handle(i);
          });
  connect(add_action(m, "Add &angle constraint...", QKeySequence("A"),
                     "Ask for a fold angle at the picked crease point (click a crease with the "
                     "crease-curves overlay on)"),
          &QAction::triggered, this, [this] {
            if (!model_) {
              report_error("Open a crease pattern first (File > Open pattern).");
              return;
            }
            const int point = picked_crease_point();
            if (point < 0) {
              report_error(
                  "Pick a crease point first: switch the crease-curves overlay on (Ctrl+9) and "
                  "click a crease "
                  "where it should fold.");
              return;
            }
            bool ok = false;
            const double degrees = QInputDialog::getDouble(
                this, "Angle constraint",
                QString("Fold angle at crease point %1, degrees: positive folds a valley (both "
                        "sides rise towards "
                        "the viewer of the flat sheet), negative a mountain, 0 keeps it flat:")
                    .arg(point),
                60, -180, 180, 1, &ok);
            if (ok) add_angle(point, degrees);
          });
  connect(add_action(m, "Remove angle constraint...", QKeySequence("Shift+A"),
                     "Remove one of the angle constraints"),
          &QAction::triggered, this, [this] {
            QStringList items;
            if (snapshot_)
              for (const auto& a : snapshot_->constraints.angles)
                items << QString("crease point %1: %2 degrees").arg(a.crease_point).arg(a.degrees);
            if (const int i = choose(this, "Remove angle constraint", items); i >= 0)
              remove_angle(i);
          });
}

void MainWindow::build_view_menu() {
  QMenu* m = menuBar()->addMenu("&View");
  int key = 1;
  for (vis::Layer layer : enum_values<vis::Layer>()) {
    // Ctrl+1 .. Ctrl+0 for the overlays, Ctrl+Shift+W for the full cells ("whole quads").
    const QKeySequence shortcut = layer == vis::Layer::kFullCells
                                      ? QKeySequence("Ctrl+Shift+W")
                                      : QKeySequence(QString("Ctrl+%1").arg(key++ % 10));
    QAction* a = add_action(m, enum_name(layer), shortcut, vis::layer_description(layer));
    a->setCheckable(true);
    connect(a, &QAction::toggled, this, [this, layer](bool on) { set_layer(layer, on); });
    layer_actions_[layer] = a;
  }
  layer_actions_.at(vis::Layer::kVertexTypes)->setChecked(true);
  layer_actions_.at(vis::Layer::kWireframe)->setChecked(true);
  m->addSeparator();
  auto* views = new QActionGroup(this);
  const std::pair<vis::View, const char*> names[] = {
      {vis::View::kThreeD, "&3D"},
      {vis::View::kFlat, "&Flat crease pattern"},
      {vis::View::kSideBySide, "Fine and coarse &side by side"}};
  int f = 2;
  for (const auto& [view, name] : names) {
    QAction* a = add_action(m, name, QKeySequence(QString("F%1").arg(f++)),
                            QString("View: ") + enum_name(view));
    a->setCheckable(true);
    a->setActionGroup(views);
    connect(a, &QAction::triggered, this, [this, view = view] { set_view(view); });
    view_actions_[view] = a;
  }
  view_actions_.at(scene_options_.view)->setChecked(true);
  coarse_action_ = add_action(m, "&Coarse mesh", QKeySequence("C"),
                              "Draw the coarse mesh's edges over the fine mesh");
  coarse_action_->setCheckable(true);
  connect(coarse_action_, &QAction::toggled, this, &MainWindow::set_coarse_visible);
  smooth_action_ = add_action(m, "S&mooth edges", QKeySequence(),
                              "Anti-aliasing of the view (FXAA); slower with software OpenGL");
  smooth_action_->setCheckable(true);
  connect(smooth_action_, &QAction::toggled, this, &MainWindow::set_smooth_edges);
  m->addSeparator();
  connect(add_action(m, "&Reset camera", QKeySequence("Home"),
                     "The view's default camera, framing the sheet as it is"),
          &QAction::triggered, this, &MainWindow::reset_camera);
  connect(add_action(m, "&Frame all", QKeySequence("F"),
                     "Keep looking the way the camera looks, and move it so that the whole sheet "
                     "as it is now fills "
                     "the view"),
          &QAction::triggered, this, &MainWindow::frame_all);
  keep_framed_action_ =
      add_action(m, "&Keep the sheet framed", QKeySequence("Shift+F"),
                 "Checkable: frame the sheet again at every new state (while playing the camera "
                 "follows the sheet)");
  keep_framed_action_->setCheckable(true);
  connect(keep_framed_action_, &QAction::toggled, this, &MainWindow::set_keep_framed);
  connect(add_action(m, "Save camera...", QKeySequence(),
                     "Save the camera pose (JSON, as sdog render --camera reads it)"),
          &QAction::triggered, this, [this] {
            const QString path = save_path_sink_("Save camera", "Cameras (*.json)");
            if (!path.isEmpty()) save_camera(path);
          });
  connect(add_action(m, "Load camera...", QKeySequence(), "Load a saved camera pose"),
          &QAction::triggered, this, [this] {
            const QString path =
                QFileDialog::getOpenFileName(this, "Load camera", {}, "Cameras (*.json)");
            if (!path.isEmpty()) load_camera(path);
          });
}

void MainWindow::build_crease_menu() {
  QMenu* m = menuBar()->addMenu("&Creases");
  for (const Fold fold : {Fold::kMountain, Fold::kValley, Fold::kFlat, Fold::kUnassigned}) {
    QString name = enum_name(fold);
    name[0] = name[0].toUpper();
    connect(
        add_action(
            m, name, QKeySequence(),
            QString(
                "Assign the picked creases %1 (click a crease with the crease-curves overlay on)")
                .arg(enum_name(fold))),
        &QAction::triggered, this, [this, fold] { set_crease_fold(fold); });
  }
  connect(add_action(m, "&Angle...", QKeySequence(),
                     "Ask for the fold angle of the picked creases (0 to 180 degrees)"),
          &QAction::triggered, this, [this] {
            if (selection_.creases().empty()) {
              report_error(
                  "Pick a crease first: switch the crease-curves overlay on (Ctrl+9) and click a "
                  "crease.");
              return;
            }
            double current = config_.fold_angle;
            const int first = selection_.creases().front();
            if (snapshot_ && first < static_cast<int>(snapshot_->crease_angles.size()) &&
                snapshot_->crease_angles[first])
              current = *snapshot_->crease_angles[first];
            bool ok = false;
            const double degrees = QInputDialog::getDouble(
                this, "Fold angle",
                "Fold angle in degrees (0 to 180; the assignment gives the direction):",
                std::abs(current), 0, 180, 1, &ok);
            if (ok) set_crease_angle(degrees);
          });
  m->addSeparator();
  connect(add_action(m, "Select all creases", QKeySequence(), "Pick every crease of the pattern"),
          &QAction::triggered, this, [this] {
            if (!model_) return;
            std::vector<int> all(model_->fine.stitching.curves.size());
            for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
            select_creases(all);
          });
  connect(add_action(m, "&Fold", QKeySequence(),
                     "Start the fold scenario from the flat sheet: every crease folds to its "
                     "assignment and angle"),
          &QAction::triggered, this, &MainWindow::fold_creases);
}

void MainWindow::build_solver_menu() {
  QMenu* m = menuBar()->addMenu("&Solver");
  play_action_ =
      add_action(m, "&Play", QKeySequence("Space"), "Iterate continuously (again: pause)");
  play_action_->setCheckable(true);
  connect(play_action_, &QAction::triggered, this, [this](bool on) { on ? play() : pause(); });
  step_action_ = add_action(m, "&Step", QKeySequence("S"), "One iteration");
  connect(step_action_, &QAction::triggered, this, [this] { step(1); });
  step10_action_ = add_action(m, "Step &10", QKeySequence("Shift+S"), "Ten iterations");
  connect(step10_action_, &QAction::triggered, this, [this] { step(10); });
  reset_action_ = add_action(m, "&Reset", QKeySequence("Ctrl+Backspace"),
                             "Back to the start state (the constraints stay)");
  connect(reset_action_, &QAction::triggered, this, &MainWindow::reset_solver);
  m->addSeparator();
  // One exclusive checkable entry per name; choosing one calls choose(name).
  auto add_choices = [this](QMenu* menu, const std::vector<std::string>& names,
                            std::map<std::string, QAction*>& actions,
                            bool (MainWindow::*choose)(const QString&)) {
    auto* group = new QActionGroup(this);
    for (const std::string& name : names) {
      QAction* a = menu->addAction(QString::fromStdString(name));
      a->setCheckable(true);
      a->setActionGroup(group);
      connect(a, &QAction::triggered, this,
              [this, name, choose] { (this->*choose)(QString::fromStdString(name)); });
      actions[name] = a;
    }
  };
  add_choices(m->addMenu("&Mode"), enum_names<ModeKind>(), mode_actions_, &MainWindow::set_mode);
  for (auto& [name, a] : mode_actions_)
    if (mode_needs_coarse(parse_enum<ModeKind>(name)))
      a->setToolTip("needs the coarse mesh (odd resolution)");
  add_choices(m->addMenu("S&cenario"), enum_names<ScenarioKind>(), scenario_actions_,
              &MainWindow::choose_scenario);
  connect(
      add_action(m, "Se&ttings", QKeySequence("Ctrl+T"),
                 "Show the Solver panel: weights, tolerances, mode options and iteration counts"),
      &QAction::triggered, this, [this] {
        solver_dock_->show();
        solver_dock_->raise();
        solver_panel_->form()->setFocus();
      });
  connect(add_action(m, "Load run &configuration...", QKeySequence(),
                     "Scenario, weights, tolerances and constraints from a JSON file (as sdog run "
                     "--config reads it)"),
          &QAction::triggered, this, &MainWindow::ask_for_run_config);
}

void MainWindow::ask_for_run_config() {
  const QString path =
      QFileDialog::getOpenFileName(this, "Run configuration", {}, "Run configurations (*.json)");
  if (!path.isEmpty()) load_run_config(path);
}

void MainWindow::build_solver_panel() {
  solver_panel_ = new SolverPanel({play_action_, step_action_, step10_action_, reset_action_});
  solver_dock_ = new QDockWidget("Solver", this);
  solver_dock_->setObjectName("solver");
  solver_dock_->setWidget(solver_panel_);
  addDockWidget(Qt::LeftDockWidgetArea, solver_dock_);
  // Wide enough for the form without a horizontal scroll bar when the window allows it.
  resizeDocks({solver_dock_}, {solver_panel_->form()->sizeHint().width() + 50}, Qt::Horizontal);
  connect(solver_panel_, &SolverPanel::mode_chosen, this, [this](const QString& mode) {
    if (!set_mode(mode)) show_solver_state();
  });
  connect(solver_panel_, &SolverPanel::scenario_chosen, this, [this](const QString& scenario) {
    if (!choose_scenario(scenario)) show_solver_state();
  });
  connect(solver_panel_, &SolverPanel::fold_percent_chosen, this, &MainWindow::set_fold_percent);
  connect(solver_panel_, &SolverPanel::config_file_wanted, this, &MainWindow::ask_for_run_config);
  // The panel does not show the crease settings: those of the session stay.
  connect(solver_panel_, &SolverPanel::apply_wanted, this, [this](RunConfig config) {
    config.creases = config_.creases;
    if (!apply_settings(config)) show_solver_state();
  });
  show_solver_state();
}

void MainWindow::show_solver_state() {
  solver_panel_->show_state(mode_, config_, model_ && model_->has_coarse);
}

void MainWindow::build_help_menu() {
  QMenu* m = menuBar()->addMenu("&Help");
  connect(add_action(m, "&Keyboard shortcuts", QKeySequence::HelpContents,
                     "Every shortcut of the menus and what the mouse does in the view"),
          &QAction::triggered, this, [this] {
            QMessageBox box(QMessageBox::NoIcon, "Keyboard shortcuts and mouse",
                            keyboard_shortcuts(), QMessageBox::Close, this);
            box.setTextFormat(Qt::RichText);
            box.exec();
          });
  connect(add_action(m, "&About", QKeySequence(), "Versions of the studio and its libraries"),
          &QAction::triggered, this,
          [this] { QMessageBox::about(this, "About Scalable DOGs studio", about_); });
  connect(add_action(m, "About &Qt", QKeySequence(), "Qt's version and license"),
          &QAction::triggered, qApp, &QApplication::aboutQt);
}

QString MainWindow::keyboard_shortcuts() const {
  QString text =
      "<table cellspacing=2><tr><th align=left>keys</th><th align=left>menu entry</th></tr>";
  for (const QMenu* menu : menuBar()->findChildren<QMenu*>()) {
    if (menu->parent() != menuBar()) continue;  // submenus hold no shortcuts
    for (const QAction* a : menu->actions()) {
      if (a->shortcut().isEmpty()) continue;
      QString entry = a->text();
      entry.remove('&');
      QString menu_name = menu->title();
      menu_name.remove('&');
      text += QString("<tr><td><b>%1</b></td><td>%2 &gt; %3</td></tr>")
                  .arg(a->shortcut().toString(QKeySequence::NativeText).toHtmlEscaped(), menu_name,
                       entry.toHtmlEscaped());
    }
  }
  text += "</table><p><b>Mouse in the 3D view</b></p><table cellspacing=2>";
  for (const auto& [action, effect] : mouse_actions())
    text += QString("<tr><td><b>%1</b></td><td>%2</td></tr>")
                .arg(QString(action).toHtmlEscaped(), QString(effect).toHtmlEscaped());
  return text + "</table>";
}

void MainWindow::update_actions() {
  for (auto& [name, a] : mode_actions_) {
    a->setChecked(name == mode_);
    a->setEnabled(model_ && (model_->has_coarse || !mode_needs_coarse(parse_enum<ModeKind>(name))));
  }
  for (auto& [name, a] : scenario_actions_) a->setChecked(name == enum_name(config_.scenario));
  play_action_->setChecked(playing_);
  play_action_->setText(playing_ ? "&Pause" : "&Play");
  undo_action_->setEnabled(snapshot_ && snapshot_->can_undo);
  redo_action_->setEnabled(snapshot_ && snapshot_->can_redo);
  const auto named = [](const char* verb, const std::string& what) {
    return what.empty() ? QString(verb) : QString("%1 %2").arg(verb, QString::fromStdString(what));
  };
  undo_action_->setText(named("&Undo", snapshot_ ? snapshot_->undo_name : std::string()));
  redo_action_->setText(named("&Redo", snapshot_ ? snapshot_->redo_name : std::string()));
}

}  // namespace sdog::studio
