#pragma once
// Picking among points already projected to the screen (display coordinates x, y and depth; the
// studio projects them through its camera, ui/studio/screen_picking.h).
#include <Eigen/Core>
#include <vector>

namespace sdog::control {

/// The row of `display` nearest (x, y), if within `max_pixels`; of the rows within a pixel of that
/// distance (copies of a crease vertex, a sheet folded over itself) the one in front (smallest
/// depth). NaN rows (behind the camera) are never picked. -1 if none.
int nearest_on_screen(const Eigen::MatrixX3d& display, double x, double y, double max_pixels);

/// Rows of `display` in the rectangle with corners (x0, y0) and (x1, y1) (any two opposite
/// corners), hidden ones included, in row order.
std::vector<int> inside_rectangle(const Eigen::MatrixX3d& display, double x0, double y0, double x1,
                                  double y1);

}  // namespace sdog::control
