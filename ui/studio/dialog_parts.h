#pragma once
// Parts the studio's dialogs share: a path field with a Browse button, and the OK / Cancel row.
#include <QString>
#include <functional>

class QDialog;
class QFormLayout;
class QHBoxLayout;
class QLineEdit;

namespace sdog::studio {

/// `field` and a Browse... button that asks `browse(current text)` for a path (empty: keep it).
QHBoxLayout* path_row(QLineEdit* field, std::function<QString(const QString&)> browse);
/// The OK (labelled `ok`) and Cancel buttons as the form's last row, accepting or rejecting
/// `dialog`.
void add_buttons(QFormLayout* form, QDialog* dialog, const QString& ok);

}  // namespace sdog::studio
