#include "ui/studio/crease_inspector.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sdog::studio {

QString describe_assignment(Fold fold, const std::optional<double>& angle, double default_degrees) {
  QString text = enum_name(fold);
  if (fold == Fold::kFlat) return text;
  if (angle) return text + QString(", %1 degrees").arg(*angle, 0, 'g', 4);
  if (fold == Fold::kUnassigned) return text;
  return text + QString(", %1 degrees (the scenario's)").arg(std::abs(default_degrees), 0, 'g', 4);
}

QString describe_creases(const DogModel& model, const std::vector<Fold>& folds,
                         const std::vector<std::optional<double>>& angles, double default_degrees,
                         const std::vector<int>& creases) {
  constexpr size_t kShown = 8;  // a longer selection is counted, not listed
  const size_t count = model.clean.creases.size();
  QString html;
  for (size_t i = 0; i < creases.size() && i < kShown; ++i) {
    const int k = creases[i];
    if (k < 0 || static_cast<size_t>(k) >= count || static_cast<size_t>(k) >= folds.size() ||
        static_cast<size_t>(k) >= angles.size())
      throw std::out_of_range("crease " + std::to_string(k) + " does not exist (the pattern has " +
                              std::to_string(count) + " creases after cleaning)");
    if (!html.isEmpty()) html += "<br>";
    html += QString("<b>crease %1</b>&nbsp; %2&nbsp; %3")
                .arg(k)
                .arg(QString::fromStdString(model.clean.creases[k].origin).toHtmlEscaped())
                .arg(describe_assignment(folds[k], angles[k], default_degrees));
  }
  if (creases.size() > kShown) html += QString("<br>... and %1 more").arg(creases.size() - kShown);
  return html;
}

}  // namespace sdog::studio
