#pragma once
// File > Export screenshot: one dialog for the file, the picture's size, its background and how
// the sheet is framed.
#include <QDialog>
#include <QString>

#include "ui/vis/offscreen.h"

class QCheckBox;
class QComboBox;
class QLineEdit;
class QSpinBox;

namespace sdog::studio {

class ExportDialog : public QDialog {
  Q_OBJECT

 public:
  /// Starts with `path` (may be empty) and `size`.
  ExportDialog(const QString& path, const vis::ImageSize& size, QWidget* parent = nullptr);

  QString path() const;
  vis::ImageSize size() const;
  bool transparent() const;
  /// The sheet framed to fill the picture (the view's direction), or the view's camera as it is.
  bool frame() const;

  // The fields, for tests.
  QLineEdit* path_field() const { return path_; }
  QSpinBox* width_field() const { return width_; }
  QSpinBox* height_field() const { return height_; }
  QCheckBox* transparent_field() const { return transparent_; }
  QComboBox* framing_field() const { return framing_; }

 private:
  QLineEdit* path_;
  QSpinBox *width_, *height_;
  QCheckBox* transparent_;
  QComboBox* framing_;
};

}  // namespace sdog::studio
