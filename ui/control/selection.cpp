#include "ui/control/selection.h"

#include <algorithm>

#include "ui/control/screen_pick.h"

namespace sdog::control {
namespace {

void add_each_once(std::vector<int>& to, int value) {
  if (std::find(to.begin(), to.end(), value) == to.end()) to.push_back(value);
}

}  // namespace

ClickPick pick_at(const DogMesh& fine, const Eigen::MatrixX3d& crease_points,
                  const Eigen::MatrixX3d& vertices, double x, double y) {
  ClickPick pick;
  const auto& curves = fine.stitching.curves;
  if (crease_points.rows() > 0 && !curves.empty()) {
    const int point = nearest_on_screen(crease_points, x, y, 8);
    for (int k = 0; point >= 0 && k < static_cast<int>(curves.size()); ++k) {
      if (std::find(curves[k].points.begin(), curves[k].points.end(), point) ==
          curves[k].points.end())
        continue;
      pick.crease = k;
      pick.crease_point = point;
      pick.message = "crease " + std::to_string(k) + " picked at crease point " +
                     std::to_string(point) +
                     " (Creases: Mountain, Valley, Angle..., Fold; Edit > Add angle constraint: A)";
      return pick;
    }
  }
  pick.vertex = nearest_on_screen(vertices, x, y, 12);
  pick.message = pick.vertex >= 0
                     ? "vertex " + std::to_string(pick.vertex) + " picked (Edit > Make handle: H)"
                     : "no vertex within 12 pixels of the click";
  return pick;
}

void Selection::select_vertices(const std::vector<int>& vertices, bool add) {
  if (!add) clear();
  for (int v : vertices) add_each_once(vertices_, v);
}

void Selection::select_creases(const std::vector<int>& creases, int crease_count, bool add) {
  if (!add) {
    creases_.clear();
    vertices_.clear();
  }
  for (int k : creases)
    if (k >= 0 && k < crease_count) add_each_once(creases_, k);
}

void Selection::apply(const ClickPick& pick, int crease_count) {
  if (pick.crease >= 0) {
    select_creases({pick.crease}, crease_count);
    picked_crease_point_ = pick.crease_point;
  } else {
    select_vertices(pick.vertex >= 0 ? std::vector<int>{pick.vertex} : std::vector<int>{});
  }
}

void Selection::clear() {
  vertices_.clear();
  creases_.clear();
  picked_crease_point_ = -1;
}

}  // namespace sdog::control
