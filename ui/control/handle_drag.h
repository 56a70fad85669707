#pragma once
// Dragging a handle's target with the mouse (Shift + drag in the studio): the grab picks the
// target drawn nearest the mouse, a target of the base scenario becomes a handle first, and the
// whole drag is one edit of the session (its first move starts the edit, the later ones merge).
#include <Eigen/Core>
#include <optional>
#include <string>

#include "solver/session/session.h"
#include "ui/vis/scene_state.h"

namespace sdog::control {

/// What a grab took: the user's handle `handle`, or (`new_handle`) the scenario's target of
/// `vertex`, which a new handle at `target` takes over as handle number `handle`.
struct Grab {
  int handle = -1;
  bool new_handle = false;
  int vertex = -1;
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double depth = 0;  ///< display depth of the target: the drag moves in the plane facing the camera
};

/// The target drawn within 15 pixels of (x, y): `drawn` are the targets the handles overlay draws
/// (the scenario's and the user's), `display` their display coordinates (same rows), `user` the
/// session's handles. None when no target is that near.
std::optional<Grab> grab_target(const vis::ConstraintView& drawn, const Eigen::MatrixX3d& display,
                                const UserConstraints& user, double x, double y);

class HandleDrag {
 public:
  void begin(const Grab& grab);
  bool active() const { return handle_ >= 0; }
  int handle() const { return handle_; }
  double depth() const { return depth_; }
  /// A move of the drag to `target`: true when it is the drag's first (it starts the edit).
  bool move();
  void end() { handle_ = -1; }
  /// "handle 2 at (1.00, 2.00, 3.00)".
  std::string describe(const Eigen::Vector3d& target) const;

 private:
  int handle_ = -1;
  double depth_ = 0;
  bool moved_ = false;  ///< the drag has sent a target (its later ones merge)
};

}  // namespace sdog::control
