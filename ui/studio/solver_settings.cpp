#include "ui/studio/solver_settings.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QSpinBox>
#include <QVBoxLayout>

namespace sdog::studio {
namespace {

QFormLayout* add_group(QVBoxLayout* layout, const QString& title) {
  auto* box = new QGroupBox(title);
  auto* form = new QFormLayout(box);
  form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
  layout->addWidget(box);
  return form;
}

}  // namespace

void SolverSettingsForm::add_double(QFormLayout* form, const QString& label,
                                    double& (*member)(RunConfig&), double min, double max,
                                    int decimals, const QString& tip) {
  auto* box = new QDoubleSpinBox;
  box->setRange(min, max);
  box->setDecimals(decimals);
  box->setToolTip(tip);
  form->addRow(label, box);
  connect(box, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &SolverSettingsForm::edited);
  fields_.push_back(
      {label, box,
       [member](RunConfig& c, QWidget* w) { static_cast<QDoubleSpinBox*>(w)->setValue(member(c)); },
       [member](RunConfig& c, const QWidget* w) {
         member(c) = static_cast<const QDoubleSpinBox*>(w)->value();
       }});
}

void SolverSettingsForm::add_int(QFormLayout* form, const QString& label,
                                 int& (*member)(RunConfig&), int min, int max, const QString& tip) {
  auto* box = new QSpinBox;
  box->setRange(min, max);
  box->setToolTip(tip);
  form->addRow(label, box);
  connect(box, qOverload<int>(&QSpinBox::valueChanged), this, &SolverSettingsForm::edited);
  fields_.push_back(
      {label, box,
       [member](RunConfig& c, QWidget* w) { static_cast<QSpinBox*>(w)->setValue(member(c)); },
       [member](RunConfig& c, const QWidget* w) {
         member(c) = static_cast<const QSpinBox*>(w)->value();
       }});
}

void SolverSettingsForm::add_bool(QFormLayout* form, const QString& label,
                                  bool& (*member)(RunConfig&), const QString& tip) {
  auto* box = new QCheckBox;
  box->setToolTip(tip);
  form->addRow(label, box);
  connect(box, &QCheckBox::toggled, this, &SolverSettingsForm::edited);
  fields_.push_back(
      {label, box,
       [member](RunConfig& c, QWidget* w) { static_cast<QCheckBox*>(w)->setChecked(member(c)); },
       [member](RunConfig& c, const QWidget* w) {
         member(c) = static_cast<const QCheckBox*>(w)->isChecked();
       }});
}

void SolverSettingsForm::add_choice(QFormLayout* form, const QString& label,
                                    int (*get)(const RunConfig&), void (*set)(RunConfig&, int),
                                    const std::vector<std::string>& names, const QString& tip) {
  QStringList choices;
  for (const auto& n : names) choices << QString::fromStdString(n);
  auto* box = new QComboBox;
  box->addItems(choices);
  box->setToolTip(tip);
  form->addRow(label, box);
  connect(box, qOverload<int>(&QComboBox::currentIndexChanged), this, &SolverSettingsForm::edited);
  fields_.push_back(
      {label, box,
       [get](RunConfig& c, QWidget* w) { static_cast<QComboBox*>(w)->setCurrentIndex(get(c)); },
       [set](RunConfig& c, const QWidget* w) {
         set(c, static_cast<const QComboBox*>(w)->currentIndex());
       }});
}

SolverSettingsForm::SolverSettingsForm(const RunConfig& config, QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  add_scenario_group(layout);
  add_weights_group(layout);
  add_standard_group(layout);
  add_patches_group(layout);
  add_coarse_group(layout);
  layout->addStretch(1);
  set_config(config);
}

void SolverSettingsForm::add_scenario_group(QVBoxLayout* layout) {
  QFormLayout* f = add_group(layout, "Scenario");
  add_int(
      f, "iterations", [](RunConfig& c) -> int& { return c.iterations; }, 1, 1000000,
      "iterations over which the scenario's targets move");
  add_int(
      f, "hold", [](RunConfig& c) -> int& { return c.hold; }, 0, 1000000,
      "iterations with the final targets");
  add_double(
      f, "fold angle", [](RunConfig& c) -> double& { return c.fold_angle; }, -180, 180, 1,
      "fold scenario: the final dihedral angle at every fold site, degrees");
}

void SolverSettingsForm::add_weights_group(QVBoxLayout* layout) {
  QFormLayout* f = add_group(layout, "Objective weights");
  const QString weight = "weight of the term in the objective (0: off)";
  add_double(
      f, "bending weight", [](RunConfig& c) -> double& { return c.weights.bending; }, 0, 1e9, 4,
      weight);
  add_double(
      f, "isometry weight", [](RunConfig& c) -> double& { return c.weights.isometry; }, 0, 1e9, 4,
      weight + " (divided by the number of quad edges)");
  add_double(
      f, "stitching weight", [](RunConfig& c) -> double& { return c.weights.stitching; }, 0, 1e9, 4,
      weight);
  add_double(
      f, "positions weight", [](RunConfig& c) -> double& { return c.weights.positions; }, 0, 1e9, 4,
      weight);
  add_double(
      f, "edge points weight", [](RunConfig& c) -> double& { return c.weights.edge_points; }, 0,
      1e9, 4, weight);
  add_double(
      f, "angles weight", [](RunConfig& c) -> double& { return c.weights.angles; }, 0, 1e9, 4,
      weight);
  add_double(
      f, "fold bias weight", [](RunConfig& c) -> double& { return c.weights.fold_bias; }, 0, 1e9, 4,
      weight);
}

void SolverSettingsForm::add_standard_group(QVBoxLayout* layout) {
  QFormLayout* f = add_group(layout, "Standard mode (SQP)");
  add_double(
      f, "KKT tolerance", [](RunConfig& c) -> double& { return c.standard.sqp.kkt_tolerance; }, 0,
      1, 9, "optimality wanted of a step");
  add_double(
      f, "constraint tolerance",
      [](RunConfig& c) -> double& { return c.standard.sqp.constraint_tolerance; }, 0, 1, 9,
      "largest DOG constraint residual wanted after every iteration");
  add_double(
      f, "final constraint tolerance",
      [](RunConfig& c) -> double& { return c.standard.sqp.final_constraint_tolerance; }, 0, 1, 9,
      "largest DOG constraint residual wanted after the last iteration");
  add_int(
      f, "SQP steps per iteration", [](RunConfig& c) -> int& { return c.standard.sqp.max_steps; },
      1, 100, "optimality steps per iteration");
}

void SolverSettingsForm::add_patches_group(QVBoxLayout* layout) {
  QFormLayout* f = add_group(layout, "Patch modes (subsolvers, ADMM)");
  add_choice(
      f, "patch backend", [](const RunConfig& c) { return static_cast<int>(c.subsolvers.backend); },
      [](RunConfig& c, int i) { c.subsolvers.backend = static_cast<PatchBackend>(i); },
      enum_names<PatchBackend>(),
      "per-patch steps: the SQP solver of the standard mode, or Ceres with an augmented Lagrangian "
      "loop");
  add_choice(
      f, "patch sweep", [](const RunConfig& c) { return static_cast<int>(c.subsolvers.sweep); },
      [](RunConfig& c, int i) { c.subsolvers.sweep = static_cast<PatchSweep>(i); },
      enum_names<PatchSweep>(),
      "subsolvers and twolevel: every patch at once from the same state (jacobi), or the patch "
      "graph's "
      "colours one after another (Gauss-Seidel by colour)");
  add_double(
      f, "Ceres constraint tolerance",
      [](RunConfig& c) -> double& { return c.subsolvers.patch.constraint_tolerance; }, 0, 1, 9,
      "Ceres backend: largest DOG constraint residual of a patch solve");
  add_double(
      f, "ADMM rho", [](RunConfig& c) -> double& { return c.admm.rho; }, 1e-9, 1e9, 6,
      "penalty of the augmented stitching terms");
  add_double(
      f, "ADMM gamma", [](RunConfig& c) -> double& { return c.admm.gamma; }, 1e-9, 10, 6,
      "damping of the jadmm / proxjadmm multiplier update");
  add_double(
      f, "ADMM P", [](RunConfig& c) -> double& { return c.admm.p; }, -1, 1e9, 6,
      "proxjadmm: proximal weight (P = p I); -1: 0.001 (patches - 1)");
  static_cast<QDoubleSpinBox*>(fields_.back().widget)
      ->setSpecialValueText("default: 0.001 (patches - 1)");
  add_int(
      f, "ADMM rounds per iteration", [](RunConfig& c) -> int& { return c.admm.inner; }, 1, 1000,
      "ADMM rounds (patch solves and multiplier updates) per solver iteration");
}

void SolverSettingsForm::add_coarse_group(QVBoxLayout* layout) {
  QFormLayout* f = add_group(layout, "Coarse modes (coarse, twolevel)");
  add_double(
      f, "coarse link weight", [](RunConfig& c) -> double& { return c.coarse.link_weight; }, 0, 1e9,
      6,
      "coarse mode: pull between fine link vertices and their coarse twins (the thesis's "
      "ftc_weight)");
  add_bool(
      f, "fine-to-coarse links", [](RunConfig& c) -> bool& { return c.coarse.fine_to_coarse; },
      "coarse mode: the coarse mesh is pulled towards the fine one too (off: --no-fine-to-coarse)");
  add_bool(
      f, "prolongate", [](RunConfig& c) -> bool& { return c.coarse.prolongate; },
      "coarse mode: each fine step starts from the coarse state carried to the fine mesh");
  add_bool(
      f, "coarse concurrent coarse step",
      [](RunConfig& c) -> bool& { return c.coarse.concurrent_coarse; },
      "coarse mode: the next iteration's coarse step runs beside this one's fine round (same "
      "results; "
      "off: one after the other)");
  add_double(
      f, "twolevel link weight", [](RunConfig& c) -> double& { return c.twolevel.link_weight; }, 0,
      1e9, 6, "twolevel mode: pull of the coarse link vertices towards their fine twins");
  add_double(
      f, "twolevel fold sharpness",
      [](RunConfig& c) -> double& { return c.twolevel.fold_sharpness; }, 1e-3, 1e6, 3,
      "twolevel mode: sharpness k of the fold bias tanh(k B.e) in its coarse step and patches");
  add_bool(
      f, "twolevel concurrent coarse step",
      [](RunConfig& c) -> bool& { return c.twolevel.concurrent_coarse; },
      "twolevel mode: the next iteration's coarse step runs beside this one's fine round (same "
      "results; "
      "off: one after the other)");
}

void SolverSettingsForm::set_config(const RunConfig& config) {
  base_ = config;
  RunConfig shown = config;  // the members are reached through non-const references
  for (const Field& f : fields_) {
    const QSignalBlocker block(f.widget);
    f.show(shown, f.widget);
  }
}

RunConfig SolverSettingsForm::config() const {
  RunConfig c = base_;
  for (const Field& f : fields_) f.store(c, f.widget);
  return c;
}

QWidget* SolverSettingsForm::field(const QString& label) const {
  for (const Field& f : fields_)
    if (f.label == label) return f.widget;
  return nullptr;
}

}  // namespace sdog::studio
