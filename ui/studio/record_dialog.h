#pragma once
// File > Record frames: the folder, what is written per recorded state (pictures, meshes,
// surfaces), how often, and whether every picture frames the sheet.
#include <QDialog>
#include <QString>

#include "ui/control/recorder.h"

class QCheckBox;
class QLineEdit;
class QSpinBox;

namespace sdog::studio {

class RecordDialog : public QDialog {
  Q_OBJECT

 public:
  explicit RecordDialog(const QString& dir, QWidget* parent = nullptr);

  QString dir() const;
  control::RecordingOptions options() const;
  bool frame() const;

 private:
  QLineEdit* dir_;
  QCheckBox *png_, *vtu_, *surface_, *frame_;
  QSpinBox* every_;
};

}  // namespace sdog::studio
