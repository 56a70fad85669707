#pragma once
// The 3D view's mouse: the trackball camera, plus a left click (press and release without moving)
// that picks, Shift + left drag that moves what the press grabbed (a handle) instead of the
// camera, and Ctrl + left drag that spans a rubber band (with Shift as well: added to the
// selection); moves without a button report hovering. Positions are VTK display coordinates.
// VTK's own key bindings (3 stereo, w/s wireframe/surface, e/q exit, f fly to, r reset, p pick, u
// user) are off: the studio's menus own the keyboard.
#include <vtkInteractorStyleTrackballCamera.h>

#include <functional>
#include <utility>
#include <vector>

namespace sdog::studio {

/// What the mouse does in the 3D view: (action, effect) pairs, as Help > Keyboard shortcuts and
/// the view's tooltip list them.
const std::vector<std::pair<const char*, const char*>>& mouse_actions();

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
  /// Ctrl + drag: the band from the press to (x, y) while the button is down ...
  std::function<void(int x0, int y0, int x, int y)> on_band;
  /// ... and when it is released (`add`: Shift was held at the press).
  std::function<void(int x0, int y0, int x1, int y1, bool add)> on_band_end;

  void OnLeftButtonDown() override;
  void OnMouseMove() override;
  void OnLeftButtonUp() override;
  /// Ignores every key (vtkInteractorStyle::OnChar would switch stereo, wireframe, exit, ...).
  void OnChar() override {}

 private:
  int press_x_ = 0, press_y_ = 0;
  bool pressed_ = false, moved_ = false, dragging_ = false, banding_ = false, band_adds_ = false;
};

}  // namespace sdog::studio
