#pragma once
// The 3D view's mouse: the trackball camera, plus a left click (press and release without moving)
// that picks, and Shift + left drag that moves what the press grabbed (a handle) instead of the
// camera; moves without a button report hovering. Positions are VTK display coordinates.
#include <vtkInteractorStyleTrackballCamera.h>

#include <functional>

namespace sdog::studio {

class ClickDragStyle : public vtkInteractorStyleTrackballCamera {
 public:
  static ClickDragStyle* New();
  vtkTypeMacro(ClickDragStyle, vtkInteractorStyleTrackballCamera);

  std::function<void(int x, int y)> on_click;
  /// The mouse moved with no button pressed.
  std::function<void(int x, int y)> on_hover;
  /// Shift + press: true when something was grabbed (the camera then stays).
  std::function<bool(int x, int y)> on_grab;
  std::function<void(int x, int y)> on_drag;
  std::function<void(int x, int y)> on_release;

  void OnLeftButtonDown() override;
  void OnMouseMove() override;
  void OnLeftButtonUp() override;

 private:
  int press_x_ = 0, press_y_ = 0;
  bool pressed_ = false, moved_ = false, dragging_ = false;
};

}  // namespace sdog::studio
