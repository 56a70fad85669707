#pragma once
// Picking in screen space: points projected through the renderer's camera, the nearest one to the
// mouse chosen (the front one among those within reach), and mouse positions taken back into the
// scene at a given depth (dragging a handle in the plane facing the camera).
#include <vtkRenderer.h>

#include <Eigen/Core>
#include <vector>

namespace sdog::studio {

/// The row of `points` (world coordinates, n x 3) nearest display position (x, y) (VTK display
/// coordinates: origin bottom left) within `max_pixels`, as control::nearest_on_screen picks it;
/// -1 if none.
int pick_point(vtkRenderer* renderer, const Eigen::MatrixX3d& points, double x, double y,
               double max_pixels);

/// Display coordinates (x, y, depth) of every row of `points` (a point behind the camera: NaN).
Eigen::MatrixX3d project_to_display(vtkRenderer* renderer, const Eigen::MatrixX3d& points);
/// Display coordinates (x, y, depth in [0, 1]) of a world point.
Eigen::Vector3d to_display(vtkRenderer* renderer, const Eigen::Vector3d& world);
/// The world point at display position (x, y) and display depth `depth`.
Eigen::Vector3d to_world(vtkRenderer* renderer, double x, double y, double depth);

}  // namespace sdog::studio
