#pragma once
// The Solver panel (a dock of the main window): play / pause, step, step 10 and reset buttons (the
// Solver menu's actions), the mode and the scenario, the fold amount slider (0 to 100% of every
// crease's angle, as Origami Simulator's fold percent), a run configuration from a file, and the
// settings form with Apply and Revert. The panel only shows and asks: the window decides (and
// reports errors) through the signals.
#include <QWidget>
#include <string>
#include <vector>

#include "solver/run/run_config.h"

class QAction;
class QComboBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSlider;
class QTimer;

namespace sdog::studio {

class SolverSettingsForm;

class SolverPanel : public QWidget {
  Q_OBJECT

 public:
  /// `controls`: the actions the buttons at the top trigger (play, step, step 10, reset).
  SolverPanel(const std::vector<QAction*>& controls, QWidget* parent = nullptr);
  /// What the window has now: the panel shows it (the form's unapplied edits are dropped).
  void show_state(const std::string& mode, const RunConfig& config, bool has_coarse);
  SolverSettingsForm* form() const { return form_; }
  QComboBox* mode_box() const { return mode_; }
  QComboBox* scenario_box() const { return scenario_; }
  QPushButton* apply_button() const { return apply_; }
  QPushButton* revert_button() const { return revert_; }
  QSlider* fold_slider() const { return fold_; }

 Q_SIGNALS:
  void mode_chosen(const QString& mode);
  void scenario_chosen(const QString& scenario);
  /// The fold amount slider moved (sent once it rests for kFoldSliderPause ms, or at release).
  void fold_percent_chosen(int percent);
  /// "From file...": the window asks for a run configuration file.
  void config_file_wanted();
  void apply_wanted(const sdog::RunConfig& config);

 private:
  QFormLayout* build_choices(QPushButton* from_file);
  /// Apply and Revert are enabled while the form holds edits not applied.
  void set_edited(bool edited);
  QComboBox* mode_;
  QComboBox* scenario_;
  QSlider* fold_;
  QLabel* fold_label_;
  QTimer* fold_pause_;  // coalesces a drag of the slider into few fold amounts
  SolverSettingsForm* form_;
  QPushButton *apply_, *revert_;
  RunConfig in_use_;  // what show_state() showed last (Revert)
};

}  // namespace sdog::studio
