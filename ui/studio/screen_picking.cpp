#include "ui/studio/screen_picking.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

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
  // Points that project within a pixel of the nearest one count as one place (copies of a crease
  // vertex, a sheet folded over itself): the front one wins.
  constexpr double kSamePlace = 1.0;
  std::vector<std::pair<double, double>> near(points.rows());  // (screen distance, depth)
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d d = to_display(renderer, points.row(i).transpose());
    near[i] = {Eigen::Vector2d(d.x() - x, d.y() - y).norm(), d.z()};
    nearest = std::min(nearest, near[i].first);
  }
  if (nearest > max_pixels) return -1;
  int best = -1;
  for (int i = 0; i < points.rows(); ++i)
    if (near[i].first <= nearest + kSamePlace && (best < 0 || near[i].second < near[best].second)) best = i;
  return best;
}

}  // namespace sdog::studio
