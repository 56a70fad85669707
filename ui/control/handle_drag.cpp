#include "ui/control/handle_drag.h"

#include <algorithm>
#include <cstdio>

#include "ui/control/screen_pick.h"

namespace sdog::control {

std::optional<Grab> grab_target(const vis::ConstraintView& drawn, const Eigen::MatrixX3d& display,
                                const UserConstraints& user, double x, double y) {
  const int picked = drawn.handles.empty() ? -1 : nearest_on_screen(display, x, y, 15);
  if (picked < 0) return std::nullopt;
  Grab grab;
  grab.vertex = drawn.handles[picked].vertex;
  grab.target = drawn.handles[picked].target;
  grab.depth = display(picked, 2);
  const auto& handles = user.handles;
  const auto own =
      std::find_if(handles.begin(), handles.end(),
                   [&](const UserConstraints::Handle& h) { return h.vertex == grab.vertex; });
  grab.new_handle = own == handles.end();
  grab.handle = static_cast<int>((grab.new_handle ? handles.end() : own) - handles.begin());
  return grab;
}

void HandleDrag::begin(const Grab& grab) {
  handle_ = grab.handle;
  depth_ = grab.depth;
  moved_ = grab.new_handle;  // adding the handle started the edit
}

bool HandleDrag::move() {
  const bool first = !moved_;
  moved_ = true;
  return first;
}

std::string HandleDrag::describe(const Eigen::Vector3d& p) const {
  char text[120];
  std::snprintf(text, sizeof text, "handle %d at (%.2f, %.2f, %.2f)", handle_, p.x(), p.y(), p.z());
  return text;
}

}  // namespace sdog::control
