#include "ui/studio/screen_picking.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>

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
  const double far = std::numeric_limits<double>::infinity();
  std::vector<std::pair<double, double>> near(points.rows(), {far, far});  // (screen distance, depth)
  double nearest = far;
  // The camera's matrix once (WorldToDisplay per point recomputes it: too slow for hovering).
  vtkMatrix4x4* world_to_view =
      renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1);
  for (int i = 0; i < points.rows(); ++i) {
    double p[4] = {points(i, 0), points(i, 1), points(i, 2), 1}, v[4];
    world_to_view->MultiplyPoint(p, v);
    if (v[3] == 0) continue;
    double dx = v[0] / v[3], dy = v[1] / v[3], dz = v[2] / v[3];
    renderer->ViewToDisplay(dx, dy, dz);
    near[i] = {Eigen::Vector2d(dx - x, dy - y).norm(), dz};
    nearest = std::min(nearest, near[i].first);
  }
  if (nearest > max_pixels) return -1;
  int best = -1;
  for (int i = 0; i < points.rows(); ++i)
    if (near[i].first <= nearest + kSamePlace && (best < 0 || near[i].second < near[best].second)) best = i;
  return best;
}

}  // namespace sdog::studio
