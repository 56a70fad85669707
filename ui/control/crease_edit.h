#pragma once
// An edit of the picked creases (the Creases menu): an assignment or a fold angle, checked, and
// the status line that says what it does.
#include <optional>
#include <string>
#include <vector>

#include "geometry/pattern/crease_pattern.h"
#include "solver/run/run_config.h"

namespace sdog::control {

/// The status line of setting the `creases` to `fold` or to `angle` degrees (one of them given)
/// in a session running `scenario`. Throws UsageError when no crease is picked or the angle is
/// outside 0 to 180 degrees.
std::string crease_edit_message(const std::vector<int>& creases, std::optional<Fold> fold,
                                std::optional<double> angle, ScenarioKind scenario);

}  // namespace sdog::control
