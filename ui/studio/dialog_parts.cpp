#include "ui/studio/dialog_parts.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>

namespace sdog::studio {

QHBoxLayout* path_row(QLineEdit* field, std::function<QString(const QString&)> browse) {
  auto* button = new QPushButton("Browse...");
  QObject::connect(button, &QPushButton::clicked, field, [field, browse = std::move(browse)] {
    const QString chosen = browse(field->text());
    if (!chosen.isEmpty()) field->setText(chosen);
  });
  auto* row = new QHBoxLayout;
  row->addWidget(field, 1);
  row->addWidget(button);
  return row;
}

void add_buttons(QFormLayout* form, QDialog* dialog, const QString& ok) {
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  buttons->button(QDialogButtonBox::Ok)->setText(ok);
  QObject::connect(buttons, &QDialogButtonBox::accepted, dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
  form->addRow(buttons);
}

}  // namespace sdog::studio
