#include "ui/studio/click_drag_style.h"

#include <vtkObjectFactory.h>
#include <vtkRenderWindowInteractor.h>

#include <cstdlib>

namespace sdog::studio {

const std::vector<std::pair<const char*, const char*>>& mouse_actions() {
  static const std::vector<std::pair<const char*, const char*>> actions = {
      {"left drag", "rotates the camera"},
      {"right drag, wheel", "zooms"},
      {"middle drag", "pans"},
      {"Shift + left drag on empty space", "pans"},
      {"click", "picks a crease (crease-curves overlay on) or the nearest vertex"},
      {"pointing", "shows the vertex under the mouse in the Inspector"},
      {"Ctrl + left drag", "selects the vertices in a rubber band"},
      {"Ctrl + Shift + left drag", "adds the vertices in a rubber band to the selection"},
      {"Shift + left drag on a target",
       "moves a handle's target, or takes over a scenario target as a handle"},
  };
  return actions;
}

vtkStandardNewMacro(ClickDragStyle);

void ClickDragStyle::OnLeftButtonDown() {
  const int* p = Interactor->GetEventPosition();
  press_x_ = p[0];
  press_y_ = p[1];
  if (Interactor->GetControlKey() && on_band) {
    banding_ = true;
    band_adds_ = Interactor->GetShiftKey() != 0;
    on_band(press_x_, press_y_, p[0], p[1]);
    return;
  }
  if (Interactor->GetShiftKey() && on_grab && on_grab(p[0], p[1])) {
    dragging_ = true;
    return;
  }
  pressed_ = true;
  moved_ = false;
  vtkInteractorStyleTrackballCamera::OnLeftButtonDown();
}

void ClickDragStyle::OnMouseMove() {
  const int* p = Interactor->GetEventPosition();
  if (dragging_) {
    if (on_drag) on_drag(p[0], p[1]);
    return;
  }
  if (banding_) {
    on_band(press_x_, press_y_, p[0], p[1]);
    return;
  }
  if (pressed_ && std::abs(p[0] - press_x_) + std::abs(p[1] - press_y_) > 3) moved_ = true;
  if (State == VTKIS_NONE && on_hover) on_hover(p[0], p[1]);
  vtkInteractorStyleTrackballCamera::OnMouseMove();
}

void ClickDragStyle::OnLeftButtonUp() {
  const int* p = Interactor->GetEventPosition();
  if (dragging_) {
    dragging_ = false;
    if (on_release) on_release(p[0], p[1]);
    return;
  }
  if (banding_) {
    banding_ = false;
    if (on_band_end) on_band_end(press_x_, press_y_, p[0], p[1], band_adds_);
    return;
  }
  vtkInteractorStyleTrackballCamera::OnLeftButtonUp();
  if (pressed_ && !moved_ && on_click) on_click(p[0], p[1]);
  pressed_ = false;
}

}  // namespace sdog::studio
