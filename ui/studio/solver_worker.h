#pragma once
// The solver thread's object: owns the Session (which is not thread safe) and does everything the
// window asks of it, one command at a time, in its thread's event loop. The window posts commands
// (post()) and receives Snapshot and IterationReport values through queued signals.
//
// While playing, the worker steps as fast as it can and reports every iteration, but sends a new
// snapshot only when the window has taken the previous one (acknowledge()), so that the view is
// never more than one state behind and the queue does not grow with states nobody will see.
#include <QObject>
#include <QString>
#include <QTimer>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "solver/run/run_config.h"
#include "solver/session/session.h"
#include "solver/session/workspace.h"
#include "ui/studio/snapshot.h"

namespace sdog::studio {

class SolverWorker : public QObject {
  Q_OBJECT

 public:
  /// Made in the window's thread, then moved to the solver thread (QObject::moveToThread).
  explicit SolverWorker(std::shared_ptr<const DogModel> model);
  ~SolverWorker() override;

  /// Runs `command` on the worker's thread (queued). Exceptions it throws become failed().
  void post(std::function<void(SolverWorker&)> command);
  /// Thread safe: the window has shown the last snapshot.
  void acknowledge() { snapshot_taken_ = true; }
  /// Thread safe (not through post()): the newest target of a handle being dragged. The worker
  /// applies the newest target when it gets to it and drops those it did not get to, so a fast
  /// mouse does not queue a rebuild per move; the moves of one drag (`first` on its first move)
  /// are one undoable edit.
  void drag_handle(int handle, const Eigen::Vector3d& target, bool first);

  // Commands (call them through post()). Each sends a snapshot afterwards.
  /// A new session; with `state` (a workspace, a saved frame) at its constraints and positions.
  void open(const RunConfig& config, const std::string& mode,
            const std::optional<Workspace>& state = std::nullopt);
  /// A new session with another configuration; `keep_shape`: at the current session's positions,
  /// iteration and constraints (new weights and tolerances act on the current shape).
  void reopen(const RunConfig& config, const std::string& mode, bool keep_shape);
  /// One iteration. While playing, an iteration that reports the shape converged after the
  /// scenario's end stops the play (stopped_converged()); the next edit of the constraints plays
  /// on. A failed iteration pauses and throws SolverError with what the user can do.
  void step();
  void play();
  void pause();
  void reset();
  void set_mode(const std::string& mode);
  void add_handles(const std::vector<int>& vertices);
  /// Session::add_handle_at: a target of the base scenario taken over by a handle (a drag starts).
  void add_handle_at(int vertex, const Eigen::Vector3d& target);
  void move_handle(int handle, const Eigen::Vector3d& target);
  void remove_handle(int handle);
  void add_angle(int crease_point, double degrees);
  void remove_angle(int angle);
  /// Session::set_creases and Session::fold.
  void set_creases(const std::vector<int>& curves, std::optional<Fold> fold,
                   std::optional<double> angle);
  void fold();
  /// Session::set_fold_percent; starts playing, so the sheet folds or unfolds at once.
  void set_fold_percent(double percent);
  void undo();
  void redo();
  void save_workspace(const std::string& path, const std::string& pattern,
                      const std::string& resolution, const nlohmann::json& camera);
  /// While the window records (every >= 1; 0: not recording), the state of every iteration that
  /// is a multiple of `every` is sent, and playing waits until the window has taken it.
  void set_recording(int every);

 Q_SIGNALS:
  void snapshot_ready(const sdog::studio::Snapshot& snapshot);
  void iterated(const sdog::IterationReport& report);
  void failed(const QString& message);
  void playing_changed(bool playing);
  void workspace_saved(const QString& path);
  /// Playing stopped by itself: the shape has converged and nothing moves.
  void stopped_converged();

 private:
  Session& session();
  void send_snapshot();
  void apply_drag();
  /// After an edit: plays on when the play stopped because the shape had converged.
  void play_on();
  struct Drag {
    int handle;
    Eigen::Vector3d target;
    bool first;
  };
  std::mutex drag_mutex_;
  std::optional<Drag> drag_;  // guarded by drag_mutex_; set: an apply_drag is queued
  std::shared_ptr<const DogModel> model_;
  std::unique_ptr<Session> session_;
  QTimer* play_timer_;
  bool stopped_converged_ = false;  ///< the play stopped by itself; an edit resumes it
  std::atomic<bool> snapshot_taken_{true};
  int record_every_ = 0;
  bool hold_ = false;  ///< playing waits for the window to take the snapshot sent (one to record)
};

}  // namespace sdog::studio
