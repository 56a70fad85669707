#include "ui/studio/record_dialog.h"

#include <QCheckBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSpinBox>

#include "ui/studio/dialog_parts.h"

namespace sdog::studio {

RecordDialog::RecordDialog(const QString& dir, QWidget* parent) : QDialog(parent) {
  setWindowTitle("Record frames");
  dir_ = new QLineEdit(dir);
  dir_->setToolTip(
      "The folder for the frames (created if needed; it must not hold another recording)");
  auto* dir_row = path_row(dir_, [this](const QString& current) {
    return QFileDialog::getExistingDirectory(this, "Folder for the frames", current);
  });
  const control::RecordingOptions defaults;
  png_ = new QCheckBox("Pictures of the view (frame_NNNN.png)");
  png_->setChecked(defaults.png);
  vtu_ = new QCheckBox("Meshes for ParaView (frame_NNNN.vtu, frames.pvd)");
  vtu_->setChecked(defaults.vtu);
  surface_ = new QCheckBox("Trimmed surfaces (surface_NNNN.vtp, surface.pvd)");
  surface_->setChecked(defaults.surface);
  every_ = new QSpinBox;
  every_->setRange(1, 100000);
  every_->setValue(defaults.every);
  every_->setPrefix("every ");
  every_->setSuffix(" iteration(s)");
  every_->setToolTip(
      "The iterations that are multiples of this are recorded (and the state when recording "
      "starts)");
  frame_ = new QCheckBox("Frame the sheet in every picture");
  frame_->setChecked(true);
  frame_->setToolTip(
      "Each picture keeps the view's direction and fits the sheet as it is then; off: the view's "
      "camera");
  auto* form = new QFormLayout(this);
  form->addRow("Folder:", dir_row);
  form->addRow("Write:", png_);
  form->addRow("", vtu_);
  form->addRow("", surface_);
  form->addRow("Record:", every_);
  form->addRow(frame_);
  add_buttons(form, this, "Record");
}

QString RecordDialog::dir() const {
  return dir_->text().trimmed();
}

control::RecordingOptions RecordDialog::options() const {
  control::RecordingOptions o;
  o.png = png_->isChecked();
  o.vtu = vtu_->isChecked();
  o.surface = surface_->isChecked();
  o.every = every_->value();
  return o;
}

bool RecordDialog::frame() const {
  return frame_->isChecked();
}

}  // namespace sdog::studio
