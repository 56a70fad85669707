#include "ui/studio/solver_panel.h"

#include <QAction>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QStandardItemModel>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

#include "solver/modes/mode_kind.h"
#include "ui/studio/solver_settings.h"

namespace sdog::studio {
namespace {

// While the fold slider is dragged, its value is sent once it has rested this long.
constexpr int kFoldSliderPause = 120;

QString percent_text(int percent) {
  return QString::number(percent) + "%";
}

}  // namespace

// The mode and scenario choices (with the button that reads a run configuration) and the fold
// slider.
QFormLayout* SolverPanel::build_choices(QPushButton* from_file) {
  auto* choices = new QFormLayout;
  mode_ = new QComboBox;
  for (const std::string& name : enum_names<ModeKind>())
    mode_->addItem(QString::fromStdString(name));
  mode_->setToolTip("How an iteration is computed; switching keeps the current state");
  choices->addRow("mode", mode_);
  auto* scenario_row = new QHBoxLayout;
  scenario_ = new QComboBox;
  for (const std::string& name : enum_names<ScenarioKind>())
    scenario_->addItem(QString::fromStdString(name));
  scenario_->setToolTip("The base scenario's targets (a new scenario starts the session again)");
  scenario_row->addWidget(scenario_, 1);
  scenario_row->addWidget(from_file);
  choices->addRow("scenario", scenario_row);
  auto* fold_row = new QHBoxLayout;
  fold_ = new QSlider(Qt::Horizontal);
  fold_->setRange(0, 100);
  fold_->setValue(100);
  fold_->setToolTip(
      "Fold amount: every crease folds to this share of its angle (0%: flat, 100%: the drawn "
      "angles); moving it starts the fold scenario and plays");
  fold_label_ = new QLabel(percent_text(100));
  fold_label_->setMinimumWidth(fold_label_->fontMetrics().horizontalAdvance("100%") + 4);
  fold_row->addWidget(fold_, 1);
  fold_row->addWidget(fold_label_);
  choices->addRow("fold amount", fold_row);
  fold_pause_ = new QTimer(this);
  fold_pause_->setSingleShot(true);
  fold_pause_->setInterval(kFoldSliderPause);
  return choices;
}

SolverPanel::SolverPanel(const std::vector<QAction*>& controls, QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);

  auto* buttons = new QHBoxLayout;
  for (QAction* action : controls) {
    auto* b = new QToolButton;
    b->setDefaultAction(action);
    b->setToolButtonStyle(Qt::ToolButtonTextOnly);
    buttons->addWidget(b);
  }
  buttons->addStretch(1);
  layout->addLayout(buttons);

  auto* from_file = new QPushButton("From file...");
  from_file->setToolTip(
      "Scenario, weights, tolerances and constraints from a run configuration (JSON, as "
      "sdog run --config reads it)");
  layout->addLayout(build_choices(from_file));

  form_ = new SolverSettingsForm(RunConfig{});
  auto* scroll = new QScrollArea;
  scroll->setWidget(form_);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);

  layout->addWidget(scroll, 1);

  auto* apply_row = new QHBoxLayout;
  apply_row->addStretch(1);
  revert_ = new QPushButton("Revert");
  revert_->setToolTip("Show the settings in use again");
  apply_ = new QPushButton("Apply");
  apply_->setToolTip(
      "Use these settings: the session starts again with them (the constraints stay)");
  apply_->setDefault(true);
  apply_row->addWidget(revert_);
  apply_row->addWidget(apply_);
  layout->addLayout(apply_row);
  set_edited(false);

  connect(mode_, qOverload<int>(&QComboBox::activated), this,
          [this](int) { Q_EMIT mode_chosen(mode_->currentText()); });
  connect(scenario_, qOverload<int>(&QComboBox::activated), this,
          [this](int) { Q_EMIT scenario_chosen(scenario_->currentText()); });
  connect(fold_, &QSlider::valueChanged, this, [this](int percent) {
    fold_label_->setText(percent_text(percent));
    fold_pause_->start();
  });
  connect(fold_pause_, &QTimer::timeout, this,
          [this] { Q_EMIT fold_percent_chosen(fold_->value()); });
  connect(fold_, &QSlider::sliderReleased, this, [this] {
    fold_pause_->stop();
    Q_EMIT fold_percent_chosen(fold_->value());
  });
  connect(from_file, &QPushButton::clicked, this, &SolverPanel::config_file_wanted);
  connect(form_, &SolverSettingsForm::edited, this, [this] { set_edited(true); });
  connect(apply_, &QPushButton::clicked, this, [this] { Q_EMIT apply_wanted(form_->config()); });
  connect(revert_, &QPushButton::clicked, this, [this] {
    form_->set_config(in_use_);
    set_edited(false);
  });
}

void SolverPanel::show_state(const std::string& mode, const RunConfig& config, bool has_coarse) {
  const QSignalBlocker block_mode(mode_), block_scenario(scenario_);
  mode_->setCurrentText(QString::fromStdString(mode));
  scenario_->setCurrentText(enum_name(config.scenario));
  {
    const QSignalBlocker block_fold(fold_);
    const int percent = static_cast<int>(std::lround(config.fold_percent));
    fold_->setValue(percent);
    fold_label_->setText(percent_text(percent));
  }
  // The coarse modes need the coarse mesh (odd resolutions): their entries are greyed out.
  if (auto* items = qobject_cast<QStandardItemModel*>(mode_->model()))
    for (int i = 0; i < mode_->count(); ++i) {
      const bool usable =
          has_coarse || !mode_needs_coarse(parse_enum<ModeKind>(mode_->itemText(i).toStdString()));
      items->item(i)->setEnabled(usable);
      items->item(i)->setToolTip(usable ? QString() : "needs the coarse mesh (an odd resolution)");
    }
  in_use_ = config;
  form_->set_config(config);
  set_edited(false);
}

void SolverPanel::set_edited(bool edited) {
  apply_->setEnabled(edited);
  revert_->setEnabled(edited);
}

}  // namespace sdog::studio
