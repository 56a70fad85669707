#pragma once
// Picking in screen space: points projected through the renderer's camera, the nearest one to the
// mouse chosen (the front one among those within reach), and mouse positions taken back into the
// scene at a given depth (dragging a handle in the plane facing the camera).
#include <vtkRenderer.h>

#include <Eigen/Core>
#include <vector>

namespace sdog::studio {

/// Index of the row of `points` (world coordinates, n x 3) whose projection is nearest display
/// position (x, y) (VTK display coordinates: origin bottom left), if within `max_pixels`; of points
/// projecting within a pixel of that distance, the one nearest the camera. -1 if none.
int pick_point(vtkRenderer* renderer, const Eigen::MatrixX3d& points, double x, double y, double max_pixels);

/// Rows of `points` whose projections lie in the rectangle with corners (x0, y0) and (x1, y1)
/// (display coordinates, any two opposite corners), hidden ones included, in row order.
std::vector<int> points_in_rectangle(vtkRenderer* renderer, const Eigen::MatrixX3d& points, double x0, double y0,
                                     double x1, double y1);

/// Display coordinates (x, y, depth) of every row of `points` (a point behind the camera: NaN).
Eigen::MatrixX3d project_to_display(vtkRenderer* renderer, const Eigen::MatrixX3d& points);
/// Display coordinates (x, y, depth in [0, 1]) of a world point.
Eigen::Vector3d to_display(vtkRenderer* renderer, const Eigen::Vector3d& world);
/// The world point at display position (x, y) and display depth `depth`.
Eigen::Vector3d to_world(vtkRenderer* renderer, double x, double y, double depth);

}  // namespace sdog::studio
