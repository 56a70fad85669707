#include "ui/studio/screen_picking.h"

#include <limits>

namespace sdog::studio {

Eigen::Vector3d to_display(vtkRenderer* renderer, const Eigen::Vector3d& world) {
  renderer->SetWorldPoint(world.x(), world.y(), world.z(), 1.0);
  renderer->WorldToDisplay();
  double d[3];
  renderer->GetDisplayPoint(d);
  return {d[0], d[1], d[2]};
}

Eigen::Vector3d to_world(vtkRenderer* renderer, double x, double y, double depth) {
  renderer->SetDisplayPoint(x, y, depth);
  renderer->DisplayToWorld();
  double w[4];
  renderer->GetWorldPoint(w);
  return Eigen::Vector3d(w[0], w[1], w[2]) / (w[3] != 0 ? w[3] : 1.0);
}

int pick_point(vtkRenderer* renderer, const Eigen::MatrixX3d& points, double x, double y, double max_pixels) {
  int best = -1;
  double best_depth = std::numeric_limits<double>::infinity();
  for (int i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d d = to_display(renderer, points.row(i).transpose());
    if (Eigen::Vector2d(d.x() - x, d.y() - y).norm() > max_pixels) continue;
    if (d.z() < best_depth) {
      best_depth = d.z();
      best = i;
    }
  }
  return best;
}

}  // namespace sdog::studio
