#include "ui/control/crease_edit.h"

#include "base/errors.h"
#include "base/text_format.h"

namespace sdog::control {

std::string crease_edit_message(const std::vector<int>& creases, std::optional<Fold> fold,
                                std::optional<double> angle, ScenarioKind scenario) {
  if (creases.empty())
    throw UsageError(
        "Pick a crease first: switch the crease-curves overlay on (Ctrl+9) and click a crease.");
  if (angle && !(*angle >= 0 && *angle <= 180))
    throw UsageError("A fold angle is from 0 to 180 degrees (its direction is the assignment's).");
  const std::string what =
      fold ? std::string(enum_name(*fold)) : format_number(*angle) + " degrees";
  return std::to_string(creases.size()) + " crease(s) set to " + what +
         (scenario == ScenarioKind::kFold
              ? " - the fold goes on from the current shape (Creases > Fold starts again from flat)"
              : " - Creases > Fold folds with the assignments");
}

}  // namespace sdog::control
