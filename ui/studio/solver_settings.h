#pragma once
// The solver settings form (the Solver panel's lower part): the scenario's iteration counts, the
// objective's weights, the standard mode's tolerances and steps, and the options of the patch,
// ADMM, coarse and two-level modes, edited as a RunConfig (the rest of the configuration, such as
// the listed constraints, is kept as it was).
#include <QString>
#include <QVBoxLayout>
#include <QWidget>
#include <functional>
#include <vector>

#include "solver/run/run_config.h"

class QFormLayout;

namespace sdog::studio {

class SolverSettingsForm : public QWidget {
  Q_OBJECT

 public:
  explicit SolverSettingsForm(const RunConfig& config, QWidget* parent = nullptr);
  /// The configuration last given (constructor or set_config) with the form's values.
  RunConfig config() const;
  /// Shows the values of `config`, which becomes the base of config().
  void set_config(const RunConfig& config);
  /// The field of a value by its label ("bending weight", "KKT tolerance", "hold", "ADMM rho",
  /// "fine-to-coarse links", ...): a QDoubleSpinBox, QSpinBox, QCheckBox or QComboBox; nullptr
  /// for an unknown label.
  QWidget* field(const QString& label) const;

 Q_SIGNALS:
  /// The user changed a value (the configuration is not applied until the panel says so).
  void edited();

 private:
  struct Field {
    QString label;
    QWidget* widget;
    std::function<void(RunConfig&, QWidget*)> show;
    std::function<void(RunConfig&, const QWidget*)> store;
  };
  void add_double(QFormLayout* form, const QString& label, double& (*member)(RunConfig&),
                  double min, double max, int decimals, const QString& tip);
  void add_int(QFormLayout* form, const QString& label, int& (*member)(RunConfig&), int min,
               int max, const QString& tip);
  void add_bool(QFormLayout* form, const QString& label, bool& (*member)(RunConfig&),
                const QString& tip);
  void add_choice(QFormLayout* form, const QString& label, int (*get)(const RunConfig&),
                  void (*set)(RunConfig&, int), const std::vector<std::string>& names,
                  const QString& tip);
  void add_scenario_group(QVBoxLayout* layout);
  void add_weights_group(QVBoxLayout* layout);
  void add_standard_group(QVBoxLayout* layout);
  void add_patches_group(QVBoxLayout* layout);
  void add_coarse_group(QVBoxLayout* layout);
  RunConfig base_;
  std::vector<Field> fields_;
};

}  // namespace sdog::studio
