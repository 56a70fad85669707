#include "ui/control/screen_pick.h"

#include <algorithm>
#include <limits>

namespace sdog::control {

int nearest_on_screen(const Eigen::MatrixX3d& display, double x, double y, double max_pixels) {
  constexpr double kSamePlace = 1.0;
  const Eigen::VectorXd distance =
      ((display.col(0).array() - x).square() + (display.col(1).array() - y).square())
          .sqrt()
          .matrix();
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < distance.size(); ++i)
    if (distance[i] < nearest) nearest = distance[i];  // NaN (behind the camera) never is
  if (!(nearest <= max_pixels)) return -1;
  int best = -1;
  for (int i = 0; i < distance.size(); ++i)
    if (distance[i] <= nearest + kSamePlace && (best < 0 || display(i, 2) < display(best, 2)))
      best = i;
  return best;
}

std::vector<int> inside_rectangle(const Eigen::MatrixX3d& display, double x0, double y0, double x1,
                                  double y1) {
  const double left = std::min(x0, x1), right = std::max(x0, x1), bottom = std::min(y0, y1),
               top = std::max(y0, y1);
  std::vector<int> inside;
  for (int i = 0; i < display.rows(); ++i)
    if (display(i, 0) >= left && display(i, 0) <= right && display(i, 1) >= bottom &&
        display(i, 1) <= top)
      inside.push_back(i);
  return inside;
}

}  // namespace sdog::control
