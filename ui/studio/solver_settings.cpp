#include "ui/studio/solver_settings.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>
#include <QVBoxLayout>

namespace sdog::studio {

SolverSettingsForm::SolverSettingsForm(const RunConfig& config, QWidget* parent) : QWidget(parent), base_(config) {
  auto* form = new QFormLayout(this);
  // A value of the configuration (`member` picks it), its range and decimals.
  auto add_double = [&](const QString& label, double& (*member)(RunConfig&), double max, int decimals,
                        const QString& tip) {
    auto* box = new QDoubleSpinBox;
    box->setRange(0, max);
    box->setDecimals(decimals);
    box->setValue(member(base_));
    box->setToolTip(tip);
    form->addRow(label, box);
    fields_.push_back({label, box, [member](RunConfig& c, const QAbstractSpinBox* b) {
                         member(c) = static_cast<const QDoubleSpinBox*>(b)->value();
                       }});
  };
  auto add_int = [&](const QString& label, int& (*member)(RunConfig&), int min, int max, const QString& tip) {
    auto* box = new QSpinBox;
    box->setRange(min, max);
    box->setValue(member(base_));
    box->setToolTip(tip);
    form->addRow(label, box);
    fields_.push_back({label, box, [member](RunConfig& c, const QAbstractSpinBox* b) {
                         member(c) = static_cast<const QSpinBox*>(b)->value();
                       }});
  };
  const QString weight = "weight of the term in the objective (0: off)";
  add_double("bending weight", [](RunConfig& c) -> double& { return c.weights.bending; }, 1e9, 4, weight);
  add_double("isometry weight", [](RunConfig& c) -> double& { return c.weights.isometry; }, 1e9, 4,
             weight + " (divided by the number of quad edges)");
  add_double("stitching weight", [](RunConfig& c) -> double& { return c.weights.stitching; }, 1e9, 4, weight);
  add_double("positions weight", [](RunConfig& c) -> double& { return c.weights.positions; }, 1e9, 4, weight);
  add_double("edge points weight", [](RunConfig& c) -> double& { return c.weights.edge_points; }, 1e9, 4, weight);
  add_double("angles weight", [](RunConfig& c) -> double& { return c.weights.angles; }, 1e9, 4, weight);
  add_double("fold bias weight", [](RunConfig& c) -> double& { return c.weights.fold_bias; }, 1e9, 4, weight);
  add_double("link weight", [](RunConfig& c) -> double& { return c.weights.link; }, 1e9, 4, weight);
  add_double("KKT tolerance", [](RunConfig& c) -> double& { return c.standard.sqp.kkt_tolerance; }, 1, 9,
             "standard mode: optimality wanted of a step");
  add_double("constraint tolerance", [](RunConfig& c) -> double& { return c.standard.sqp.constraint_tolerance; }, 1, 9,
             "standard mode: largest DOG constraint residual wanted after every iteration");
  add_double("final constraint tolerance",
             [](RunConfig& c) -> double& { return c.standard.sqp.final_constraint_tolerance; }, 1, 9,
             "standard mode: largest DOG constraint residual wanted after the last iteration");
  add_int("SQP steps per iteration", [](RunConfig& c) -> int& { return c.standard.sqp.max_steps; }, 1, 100,
          "standard mode: optimality steps per iteration");
  add_int("iterations", [](RunConfig& c) -> int& { return c.iterations; }, 1, 1000000,
          "iterations over which the scenario's targets move");
  add_int("hold", [](RunConfig& c) -> int& { return c.hold; }, 0, 1000000, "iterations with the final targets");
}

RunConfig SolverSettingsForm::config() const {
  RunConfig c = base_;
  for (const Field& f : fields_) f.store(c, f.box);
  return c;
}

QAbstractSpinBox* SolverSettingsForm::field(const QString& label) const {
  for (const Field& f : fields_)
    if (f.label == label) return f.box;
  return nullptr;
}

std::optional<RunConfig> edit_solver_settings(QWidget* parent, const RunConfig& config) {
  QDialog dialog(parent);
  dialog.setWindowTitle("Solver settings");
  auto* layout = new QVBoxLayout(&dialog);
  auto* form = new SolverSettingsForm(config);
  layout->addWidget(form);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  layout->addWidget(buttons);
  if (dialog.exec() != QDialog::Accepted) return std::nullopt;
  return form->config();
}

}  // namespace sdog::studio
