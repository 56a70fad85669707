#pragma once
// The Solver > Settings form: the objective's weights, the standard mode's tolerances and steps,
// and the scenario's iteration counts, edited as a RunConfig (the rest of the configuration is
// kept as it was).
#include <QAbstractSpinBox>
#include <QString>
#include <QWidget>
#include <functional>
#include <optional>
#include <vector>

#include "solver/run_config.h"

namespace sdog::studio {

class SolverSettingsForm : public QWidget {
  Q_OBJECT

 public:
  explicit SolverSettingsForm(const RunConfig& config, QWidget* parent = nullptr);
  /// The configuration given to the constructor with the form's values.
  RunConfig config() const;
  /// The field of a value by its label ("bending weight", "KKT tolerance", "iterations", ...);
  /// nullptr for an unknown label.
  QAbstractSpinBox* field(const QString& label) const;

 private:
  struct Field {
    QString label;
    QAbstractSpinBox* box;
    std::function<void(RunConfig&, const QAbstractSpinBox*)> store;
  };
  RunConfig base_;
  std::vector<Field> fields_;
};

/// A modal dialog with the form; the edited configuration, or nothing when cancelled.
std::optional<RunConfig> edit_solver_settings(QWidget* parent, const RunConfig& config);

}  // namespace sdog::studio
