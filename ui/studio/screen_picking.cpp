#include "ui/studio/screen_picking.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>

#include "ui/control/screen_pick.h"

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

Eigen::MatrixX3d project_to_display(vtkRenderer* renderer, const Eigen::MatrixX3d& points) {
  // The camera's matrix once (WorldToDisplay per point recomputes it: too slow for hovering).
  vtkMatrix4x4* world_to_view = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
      renderer->GetTiledAspectRatio(), -1, 1);
  Eigen::MatrixX3d display(points.rows(), 3);
  for (int i = 0; i < points.rows(); ++i) {
    double p[4] = {points(i, 0), points(i, 1), points(i, 2), 1}, v[4];
    world_to_view->MultiplyPoint(p, v);
    if (!(v[3] > 0)) {
      display.row(i).setConstant(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    double dx = v[0] / v[3], dy = v[1] / v[3], dz = v[2] / v[3];
    renderer->ViewToDisplay(dx, dy, dz);
    display.row(i) << dx, dy, dz;
  }
  return display;
}

int pick_point(vtkRenderer* renderer, const Eigen::MatrixX3d& points, double x, double y,
               double max_pixels) {
  return control::nearest_on_screen(project_to_display(renderer, points), x, y, max_pixels);
}

}  // namespace sdog::studio
