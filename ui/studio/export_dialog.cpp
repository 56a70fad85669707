#include "ui/studio/export_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSpinBox>

#include "ui/studio/dialog_parts.h"

namespace sdog::studio {

ExportDialog::ExportDialog(const QString& path, const vis::ImageSize& size, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle("Export screenshot");
  path_ = new QLineEdit(path);
  path_->setToolTip("The PNG file to write (.png is added to a name without an extension)");
  auto* file_row = path_row(path_, [this](const QString& current) {
    return QFileDialog::getSaveFileName(this, "Export screenshot", current, "PNG images (*.png)");
  });
  auto spin = [](int value, const QString& tip) {
    auto* s = new QSpinBox;
    s->setRange(64, 8192);
    s->setValue(value);
    s->setSuffix(" px");
    s->setToolTip(tip);
    return s;
  };
  width_ = spin(size.width, "Width of the picture in pixels");
  height_ = spin(size.height, "Height of the picture in pixels");
  auto* size_row = new QHBoxLayout;
  size_row->addWidget(width_);
  size_row->addWidget(height_);
  transparent_ = new QCheckBox("Transparent background");
  framing_ = new QComboBox;
  framing_->addItem("Frame the sheet (fill the picture)");
  framing_->addItem("The view's camera as it is");
  framing_->setToolTip(
      "Framing keeps the direction the view looks from and moves the camera so that the sheet "
      "fills "
      "the picture");
  auto* form = new QFormLayout(this);
  form->addRow("File:", file_row);
  form->addRow("Size:", size_row);
  form->addRow("Camera:", framing_);
  form->addRow(transparent_);
  add_buttons(form, this, "Export");
}

QString ExportDialog::path() const {
  return path_->text().trimmed();
}
vis::ImageSize ExportDialog::size() const {
  return {width_->value(), height_->value()};
}
bool ExportDialog::transparent() const {
  return transparent_->isChecked();
}
bool ExportDialog::frame() const {
  return framing_->currentIndex() == 0;
}

}  // namespace sdog::studio
