#pragma once
// The studio's main window: a 3D view of the model (vis::Scene in a QVTKOpenGLNativeWidget), the
// solver on its own thread (SolverWorker), a live chart of the iterations, the inspector of the
// picked vertex or creases, menus File / Edit / View / Creases / Solver / Help.
//
// Every public operation is what a menu entry does, without dialogs, so that tests and the
// command line drive the window as a user would. Errors go to the error sink (a message box by
// default); operations that can fail return false after reporting.
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <QLabel>
#include <QMainWindow>
#include <QStringList>
#include <QThread>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "solver/run/run_config.h"
#include "solver/session/workspace.h"
#include "ui/control/handle_drag.h"
#include "ui/control/recorder.h"
#include "ui/control/selection.h"
#include "ui/studio/snapshot.h"
#include "ui/vis/layers.h"
#include "ui/vis/offscreen.h"
#include "ui/vis/picture.h"
#include "ui/vis/scene.h"

class QAction;
class QDockWidget;
class QVTKOpenGLNativeWidget;

namespace sdog::studio {

class ObjectiveChart;
class SelectionMarks;
class SolverPanel;
class SolverWorker;

/// `path` with `.extension` appended when its file name has no extension (what the save dialogs
/// do with a name typed without one).
QString with_extension(const QString& path, const QString& extension);

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// `about` is the text of Help > About (the versions the program was built with).
  explicit MainWindow(const QString& about, QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Where error messages go (default: a modal message box).
  void set_error_sink(std::function<void(const QString&)> sink) { error_sink_ = std::move(sink); }
  /// How the window asks a question: the index of the answer chosen in `answers` (the last one is
  /// the cancelling one, also when the question is dismissed). Default: a message box.
  void set_question_sink(
      std::function<int(const QString& question, const QStringList& answers)> sink) {
    question_sink_ = std::move(sink);
  }
  /// How the window asks for a file to save to (dialog title, file filter; empty: cancelled).
  /// Default: a file dialog.
  void set_save_path_sink(
      std::function<QString(const QString& title, const QString& filter)> sink) {
    save_path_sink_ = std::move(sink);
  }

  // File
  /// Meshes the pattern and starts a session on it with the current run configuration. A run
  /// configuration loaded (or crease assignments set) for another pattern is dropped first, which
  /// the status bar says.
  bool open_pattern(const QString& path, const QString& resolution,
                    const QString& mode = "standard");
  /// The same pattern at another resolution (the mode stays if it can run there).
  bool change_resolution(const QString& resolution);
  bool open_workspace(const QString& path);
  /// The session has changed (an iteration, an edit, new settings) since it was opened or saved.
  bool modified() const { return modified_; }
  /// Before `action` ("closing", "opening another pattern", ...) that would end a modified
  /// session: asks whether to save it (Save..., Discard, Cancel) and saves it when asked. False:
  /// the user cancelled, or the save failed (the action should not happen).
  bool settle_unsaved(const QString& action);
  /// A workspace's state on a model built by the caller (sdog-studio --frame: a saved frame on the
  /// model of its run, meshed with the run's options); `source` names the file it came from.
  bool open_state(std::shared_ptr<const DogModel> model, const Workspace& state,
                  const QString& source);
  /// Saved by the solver thread (`.json` appended to a name without an extension);
  /// workspace_saved() follows, and the status bar names the file.
  bool save_workspace(const QString& path);
  /// The current view rendered offscreen at the given size (`.png` appended to a name without an
  /// extension) with the view's camera, or (`frame`) its direction with the sheet framed to fill
  /// the picture. The status bar names the file.
  bool export_screenshot(const QString& path, const vis::ImageSize& size, bool transparent,
                         bool frame = false);
  /// The trimmed surface of the current state in sheet units (vis/surface_files.h): OBJ or PLY as
  /// the path's extension says (.obj appended when it names neither); a PLY is coloured by the
  /// colour overlay that is on (patches when none is). The status bar names the file written.
  bool export_surface(const QString& path);
  /// Records into `dir` (recorder.h): the current state, then the iterations that are multiples of
  /// `options.every`, as they are shown. `frame`: every picture frames the sheet (the view's
  /// direction). The status bar shows the count and size while recording.
  bool start_frames(const QString& dir, const control::RecordingOptions& options = {},
                    bool frame = true);
  /// Ends the recording; frames_written() follows.
  void stop_frames();
  bool recording_frames() const { return recorder_ != nullptr; }
  int frames_recorded() const;
  QString recording_indicator() const;
  /// The whole window as it is on screen; `frame_sheet`: the view frames the sheet first (View >
  /// Frame all), as sdog-studio --screenshot does.
  bool save_window_image(const QString& path, bool frame_sheet = false);

  // View
  void set_layer(vis::Layer layer, bool on);
  void set_view(vis::View view);
  void set_coarse_visible(bool on);
  /// Anti-aliasing of the 3D view (FXAA; off by default: it costs frames with software OpenGL).
  void set_smooth_edges(bool on);
  bool smooth_edges() const { return renderer_->GetUseFXAA(); }
  void reset_camera();
  /// The camera, looking the way it looks, moved to frame the sheet as it is now (View > Frame
  /// all).
  void frame_all();
  /// Every new state shown is framed (View > Keep the sheet framed; off by default).
  void set_keep_framed(bool on);
  /// Draws the 3D view now (what the mouse's camera moves do).
  void render();
  bool save_camera(const QString& path);
  bool load_camera(const QString& path);

  // Solver and editing (sent to the solver thread; the results come back as snapshots)
  void step(int iterations = 1);
  void play();
  void pause();
  void reset_solver();
  bool set_mode(const QString& mode);
  bool set_scenario(const QString& scenario);
  /// What Solver > Scenario does: asks first when the session has left its start state (the
  /// shape would be lost), then set_scenario.
  bool choose_scenario(const QString& scenario);
  bool load_run_config(const QString& path);
  /// Another run configuration (Solver > Settings): checked, then a new session starts, from the
  /// scenario's start state or (`keep_shape`) at the current positions, iteration and constraints.
  bool set_run_config(const RunConfig& config, bool keep_shape = false);
  /// What Apply in the Solver panel does: when the session has left its start state, asks
  /// whether the new settings act on the current shape or start again (or cancels), then
  /// set_run_config. The status bar says which.
  bool apply_settings(const RunConfig& config);
  const RunConfig& run_config() const { return config_; }
  void add_handle(int vertex);
  /// Every vertex of the list a handle, as one edit (Edit > Make handle on a selection).
  void add_handles(const std::vector<int>& vertices);
  void move_handle(int handle, const Eigen::Vector3d& target);
  /// A move of a handle during a mouse drag (`first`: the drag's first; a drag is one edit).
  void drag_handle(int handle, const Eigen::Vector3d& target, bool first);
  void remove_handle(int handle);
  void add_angle(int crease_point, double degrees);
  void remove_angle(int angle);
  void undo();
  void redo();
  /// Picks the vertex (the selection becomes it; Edit > Make handle uses it) and shows it in the
  /// inspector (-1: none).
  void select_vertex(int vertex);
  /// The selection becomes `vertices` (with `add`: they are added to it), as the rubber band does.
  void select_vertices(const std::vector<int>& vertices, bool add = false);
  /// The fine vertices in the rectangle between two display positions of the 3D view (the rubber
  /// band: Ctrl + drag) are selected.
  void select_in_rectangle(double x0, double y0, double x1, double y1, bool add = false);
  const std::vector<int>& selection() const { return selection_.vertices(); }
  /// What a click at display position (x, y) of the 3D view does: with the crease-curves layer on,
  /// the crease through the nearest crease point within 8 pixels is picked; otherwise (or when
  /// there is none) the nearest vertex within 12 pixels.
  void click(double x, double y);

  // Creases (Creases menu): the picked creases, their assignment and angle (each change one
  // undoable edit of the session), and the fold scenario with them.
  /// The crease selection becomes `creases` (with `add`: they are added); shown in the inspector.
  void select_creases(const std::vector<int>& creases, bool add = false);
  const std::vector<int>& selected_creases() const { return selection_.creases(); }
  /// The crease point of the last crease picked by a click (-1: none): where Edit > Add angle
  /// constraint asks for an angle.
  int picked_crease_point() const { return selection_.picked_crease_point(); }
  void set_crease_fold(Fold fold);
  /// Fold angle in degrees (0 to 180) of the selected creases; their assignment stays.
  void set_crease_angle(double degrees);
  /// Starts the fold scenario from the flat sheet with the current assignments.
  void fold_creases();
  /// The fold amount slider: the session folds to `percent` of every crease's angle and plays.
  void set_fold_percent(int percent);

  // State, for tests and the command line
  const DogModel* model() const { return model_.get(); }
  /// The last state shown (nullptr before the first).
  const Snapshot* snapshot() const { return snapshot_ ? &*snapshot_ : nullptr; }
  int reports_received() const { return reports_received_; }
  bool playing() const { return playing_; }
  int selected_vertex() const { return selection_.vertex(); }
  QString inspector_text() const;
  QString status_text() const;
  vis::Scene* scene() const { return scene_.get(); }
  vtkRenderer* renderer() const { return renderer_; }
  /// The 3D view's interactor (its style picks on click and drags handles with Shift).
  vtkRenderWindowInteractor* interactor() const;
  const ObjectiveChart* chart() const { return chart_; }
  /// The text of Help > Keyboard shortcuts: every menu entry with a shortcut, and the mouse.
  QString keyboard_shortcuts() const;
  /// Starts dragging the handle or base-scenario target drawn within 15 pixels of display
  /// position (x, y) (the Shift + drag of the mouse); a scenario target becomes a handle first.
  bool grab_target(double x, double y);
  SolverPanel* solver_panel() const { return solver_panel_; }
  QAction* layer_action(vis::Layer layer) const { return layer_actions_.at(layer); }

 Q_SIGNALS:
  void snapshot_shown();
  void workspace_saved(const QString& path);
  void frames_written(const QString& dir, int count);

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;
  void closeEvent(QCloseEvent* event) override;

 private:
  /// Shows `model` (of the pattern at `path`) and starts a session on it in `mode` with the run
  /// configuration, at `state` when given.
  void show_model(std::shared_ptr<const DogModel> model, const QString& path,
                  const std::string& mode, const std::optional<Workspace>& state);
  /// The session has left its start state: an iteration, a handle or an angle constraint.
  bool left_start() const;
  void build_menus();
  void build_file_menu();
  void add_export_actions(QMenu* m);
  void build_edit_menu();
  void build_view_menu();
  void build_crease_menu();
  void build_solver_menu();
  void build_help_menu();
  void build_solver_panel();
  /// The Solver panel shows the mode and configuration in use (unapplied edits are dropped).
  void show_solver_state();
  /// A file dialog for a run configuration, then load_run_config().
  void ask_for_run_config();
  void set_up_mouse();
  void report_error(const QString& message);
  /// Runs `what`; an exception becomes an error message and false.
  bool attempt(const std::function<void()>& what);
  void post(std::function<void(SolverWorker&)> command);
  void stop_worker();
  void start_worker();
  void show_snapshot(const Snapshot& snapshot);
  void show_report(const IterationReport& report);
  /// How exported pictures and recorded frames draw the view: its layers, options and camera.
  vis::PictureOptions picture_options(const vis::ImageSize& size) const;
  /// Records the state shown when the recording is due for it.
  void record_frame();
  void update_recording_indicator();
  /// The crease curves of the model (0 before one is open).
  int crease_count() const;
  /// Sends a crease edit of the selection to the session (false: nothing selected or a bad angle,
  /// said).
  bool edit_creases(std::optional<Fold> fold, std::optional<double> angle);
  /// The hovered vertex (-1: none, then the picked vertex or creases) in the inspector.
  void show_in_inspector(int hovered);
  /// Where the view draws the fine vertices (the flat view: the rest state). Needs a snapshot.
  Eigen::MatrixX3d shown_positions() const;
  /// The selection's dots follow the shown positions.
  void refresh_selection_marks();
  void update_actions();
  void open_file(const QString& path);
  nlohmann::json camera_json() const;

  QString about_;
  std::function<void(const QString&)> error_sink_;
  std::function<int(const QString&, const QStringList&)> question_sink_;
  std::function<QString(const QString&, const QString&)> save_path_sink_;
  bool modified_ = false;
  bool keep_framed_ = false;
  bool scenario_end_marked_ = false;  // the chart marks the iteration the scenario's targets stop
  bool wireframe_chosen_ = false;     // the user set the wireframe: no default by mesh size

  // The open pattern; the scene and the worker refer to the model.
  QString pattern_path_, resolution_;
  std::string mode_ = "standard";
  RunConfig config_;
  // The run configuration's file (or workspace) and the pattern it was loaded or its creases set
  // for; opening another pattern drops it (empty: the configuration fits any pattern).
  QString config_file_, config_pattern_;
  std::shared_ptr<const DogModel> model_;
  std::unique_ptr<vis::Scene> scene_;
  vis::SceneOptions scene_options_;
  std::optional<Snapshot> snapshot_;
  std::optional<nlohmann::json> pending_camera_;  // from a workspace, applied with its first state
  bool camera_fitted_ = false;

  QThread solver_thread_;
  SolverWorker* worker_ = nullptr;
  int generation_ = 0;  // of the worker; states from an earlier one are dropped
  bool playing_ = false;
  int reports_received_ = 0;
  int hovered_vertex_ = -1;
  control::Selection selection_;
  std::unique_ptr<SelectionMarks> marks_;
  control::HandleDrag drag_;

  std::unique_ptr<control::Recorder> recorder_;
  bool record_framed_ = true;
  QString last_recording_dir_, last_screenshot_;  // what the dialogs offer next time
  vis::ImageSize last_screenshot_size_{1600, 900};
  QLabel* recording_label_ = nullptr;

  QVTKOpenGLNativeWidget* view_;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> render_window_;
  vtkSmartPointer<vtkRenderer> renderer_;
  ObjectiveChart* chart_;
  QLabel* inspector_;
  QLabel* status_;

  std::map<vis::Layer, QAction*> layer_actions_;
  std::map<std::string, QAction*> mode_actions_, scenario_actions_;
  std::map<vis::View, QAction*> view_actions_;
  QAction *play_action_ = nullptr, *undo_action_ = nullptr, *redo_action_ = nullptr,
          *coarse_action_ = nullptr;
  QAction *frames_action_ = nullptr, *smooth_action_ = nullptr, *keep_framed_action_ = nullptr;
  QAction *step_action_ = nullptr, *step10_action_ = nullptr, *reset_action_ = nullptr;
  SolverPanel* solver_panel_ = nullptr;
  QDockWidget* solver_dock_ = nullptr;
};

}  // namespace sdog::studio
