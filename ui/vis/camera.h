#pragma once
// Cameras of a scene: the fixed defaults of each view (so that pictures are reproducible) and
// camera poses saved to and loaded from JSON (the studio's "save camera").
//
// Defaults (the drawing fills the part of the viewport left of the legend column, x < 0.75 of the
// width, with a margin; the camera's window centre is shifted to the middle of that part):
// - top view (flat and side-by-side): parallel projection looking down -z, view up +y, centred on
//   the bounds of what is drawn, which fill at most 90% of the width and 85% of the height of the
//   drawing area;
// - 3D view: perspective with a 30 degree view angle, looking at the centre of the bounds from
//   the direction (0.9, -1.2, 1) (front right, above the sheet), view up +z, at the distance at
//   which the bounding sphere fills the drawing area.
#include <vtkCamera.h>

#include <Eigen/Core>
#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sdog::vis {

struct CameraPose {
  Eigen::Vector3d position{0, 0, 1}, focal_point{0, 0, 0}, view_up{0, 1, 0};
  double view_angle = 30;  ///< degrees (perspective)
  bool parallel = false;
  double parallel_scale = 1;            ///< half the viewport height in world units (parallel)
  Eigen::Vector2d window_center{0, 0};  ///< vtkCamera::SetWindowCenter, viewport units [-1, 1]
};

/// Bounds xmin, xmax, ymin, ymax, zmin, zmax (the vtkProp convention).
using Bounds = std::array<double, 6>;

/// The default cameras above for a viewport of aspect ratio width / height, framing the bounds
/// in the drawing area: the viewport left of the legend column, or (legend_column false) the whole
/// viewport. The 3D camera looks from the front right, above, from just far enough for every
/// corner of the bounds to lie inside the drawing area.
CameraPose top_view_camera(const Bounds& bounds, double aspect, bool legend_column = true);
CameraPose three_d_camera(const Bounds& bounds, double aspect, bool legend_column = true);
/// The 3D camera framing the points themselves (tighter than their bounds): every point inside
/// the drawing area, their projection centred in it.
CameraPose three_d_camera(const std::vector<Eigen::Vector3d>& points, double aspect,
                          bool legend_column = true);
/// The camera `from` (its direction, view up and projection) moved so that every point lies
/// inside the drawing area, their projection centred in it: View > Frame all.
CameraPose framed_camera(const std::vector<Eigen::Vector3d>& points, const CameraPose& from,
                         double aspect, bool legend_column = true);

CameraPose camera_pose(vtkCamera* camera);
void apply_camera_pose(const CameraPose& pose, vtkCamera* camera);

/// {"position": [x, y, z], "focal_point": [...], "view_up": [...], "view_angle": 30,
///  "parallel": false, "parallel_scale": 1, "window_center": [0, 0]}
nlohmann::json to_json(const CameraPose& pose);
/// Every key is required; throws InputError naming `source` and the key.
CameraPose camera_pose_from_json(const nlohmann::json& json, const std::string& source);

/// Writes the pose as JSON (under a temporary name, then renamed); throws OutputError.
void save_camera(const CameraPose& pose, const std::string& path);
/// Throws InputError naming the file (unreadable, not JSON, a missing or bad key).
CameraPose load_camera(const std::string& path);

}  // namespace sdog::vis
