#include "ui/vis/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "base/atomic_output.h"
#include "base/errors.h"
#include "ui/vis/legends.h"

namespace sdog::vis {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The drawing area: the viewport left of the legend column, its centre in viewport units [-1, 1].
constexpr double kDrawingWidth = kLegendColumnLeft;
const Eigen::Vector2d kDrawingCentre{kDrawingWidth - 1, 0};
// The share of the height a 3D view fills when a caption may sit at the top.
constexpr double kCaptionFreeHeight = 0.88;

Eigen::Vector3d centre(const Bounds& b) {
  return {0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])};
}

// The camera's window centre that puts the focal point in the middle of the drawing area.
Eigen::Vector2d drawing_window_center(bool legend_column) {
  return legend_column ? Eigen::Vector2d(-kDrawingCentre) : Eigen::Vector2d::Zero();
}

Eigen::Vector3d vector3(const nlohmann::json& json, const char* key, const std::string& source) {
  const auto& v = json.at(key);
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    throw InputError(source + ": $." + key + ": expected an array of 3 numbers");
  return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

}  // namespace

CameraPose top_view_camera(const Bounds& b, double aspect, bool legend_column) {
  CameraPose pose;
  const Eigen::Vector3d c = centre(b);
  const double w = std::max(b[1] - b[0], 1e-9), h = std::max(b[3] - b[2], 1e-9);
  const double drawing_width = legend_column ? kDrawingWidth : 1.0;
  pose.parallel = true;
  pose.parallel_scale = std::max(h / (2 * 0.85), w / (2 * 0.9 * aspect * drawing_width));
  pose.focal_point = c;
  pose.position = c + Eigen::Vector3d(0, 0, 4 * std::max({w, h, b[5] - b[4]}));
  pose.view_up = {0, 1, 0};
  pose.window_center = drawing_window_center(legend_column);
  return pose;
}

CameraPose three_d_camera(const Bounds& b, double aspect, bool legend_column) {
  std::vector<Eigen::Vector3d> corners;
  for (int k = 0; k < 8; ++k)
    corners.emplace_back(b[k & 1], b[2 + ((k >> 1) & 1)], b[4 + ((k >> 2) & 1)]);
  return three_d_camera(corners, aspect, legend_column);
}

CameraPose three_d_camera(const std::vector<Eigen::Vector3d>& points, double aspect,
                          bool legend_column) {
  CameraPose pose;
  pose.view_up = {0, 0, 1};
  pose.position = pose.focal_point + Eigen::Vector3d(0.9, -1.2, 1);
  return framed_camera(points, pose, aspect, legend_column);
}

CameraPose framed_camera(const std::vector<Eigen::Vector3d>& points, const CameraPose& from,
                         double aspect, bool legend_column) {
  // The margin around the points' projection, as a factor of the distance (of the extent in a
  // parallel projection).
  constexpr double kMargin = 1.06;
  CameraPose pose = from;
  pose.window_center = drawing_window_center(legend_column);
  if (points.empty()) return pose;
  Eigen::Vector3d towards_camera = from.position - from.focal_point;
  if (towards_camera.norm() < 1e-12) towards_camera = Eigen::Vector3d(0, 0, 1);
  towards_camera.normalize();
  Eigen::Vector3d right = from.view_up.cross(towards_camera);
  if (right.norm() < 1e-9) {  // view up along the view direction: any perpendicular one
    right = Eigen::Vector3d(1, 0, 0).cross(towards_camera);
    if (right.norm() < 1e-9) right = Eigen::Vector3d(0, 1, 0).cross(towards_camera);
    pose.view_up = towards_camera.cross(right.normalized());
  }
  right.normalize();
  const Eigen::Vector3d up = towards_camera.cross(right);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : points) c += p;
  c /= static_cast<double>(points.size());
  // With the legend column, the caption takes the top of the drawing area.
  const double height_share = legend_column ? kCaptionFreeHeight : 1.0;
  const double width_share = aspect * (legend_column ? kDrawingWidth : 1.0);
  if (from.parallel) {
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300, depth = 0;
    for (const auto& p : points) {
      const Eigen::Vector3d rel = p - c;
      lo_x = std::min(lo_x, rel.dot(right)), hi_x = std::max(hi_x, rel.dot(right));
      lo_y = std::min(lo_y, rel.dot(up)), hi_y = std::max(hi_y, rel.dot(up));
      depth = std::max(depth, std::abs(rel.dot(towards_camera)));
    }
    c += 0.5 * (lo_x + hi_x) * right + 0.5 * (lo_y + hi_y) * up;
    const double half_w = std::max(0.5 * (hi_x - lo_x), 1e-9),
                 half_h = std::max(0.5 * (hi_y - lo_y), 1e-9);
    pose.parallel_scale = kMargin * std::max(half_h / height_share, half_w / width_share);
    pose.focal_point = c;
    pose.position = c + (4 * std::max({half_w, half_h, depth}) + 1) * towards_camera;
    return pose;
  }
  const double tan_half = std::tan(0.5 * pose.view_angle * kPi / 180);
  const double tan_y = tan_half * height_share, tan_x = tan_half * width_share;
  // A point at lateral offsets (x, y) and depth z towards the camera lies inside the drawing area
  // at distance d when |x| <= tan_x (d - z) and |y| <= tan_y (d - z). The focal point moves to
  // the middle of the projection from the points' centroid, then the distance is found again.
  double distance = 1e-9;
  for (int pass = 0; pass < 2; ++pass) {
    distance = 1e-9;
    for (const auto& p : points) {
      const Eigen::Vector3d rel = p - c;
      const double z = rel.dot(towards_camera);
      distance = std::max(
          {distance, z + std::abs(rel.dot(right)) / tan_x, z + std::abs(rel.dot(up)) / tan_y});
    }
    if (pass == 1) break;
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (const auto& p : points) {
      const Eigen::Vector3d rel = p - c;
      const double depth = distance - rel.dot(towards_camera);
      lo_x = std::min(lo_x, rel.dot(right) / depth), hi_x = std::max(hi_x, rel.dot(right) / depth);
      lo_y = std::min(lo_y, rel.dot(up) / depth), hi_y = std::max(hi_y, rel.dot(up) / depth);
    }
    c += distance * (0.5 * (lo_x + hi_x) * right + 0.5 * (lo_y + hi_y) * up);
  }
  pose.focal_point = c;
  pose.position = c + kMargin * distance * towards_camera;
  return pose;
}

CameraPose camera_pose(vtkCamera* camera) {
  CameraPose pose;
  camera->GetPosition(pose.position.data());
  camera->GetFocalPoint(pose.focal_point.data());
  camera->GetViewUp(pose.view_up.data());
  pose.view_angle = camera->GetViewAngle();
  pose.parallel = camera->GetParallelProjection() != 0;
  pose.parallel_scale = camera->GetParallelScale();
  camera->GetWindowCenter(pose.window_center.data());
  return pose;
}

void apply_camera_pose(const CameraPose& pose, vtkCamera* camera) {
  camera->SetFocalPoint(pose.focal_point.data());
  camera->SetPosition(pose.position.data());
  camera->SetViewUp(pose.view_up.data());
  camera->SetViewAngle(pose.view_angle);
  camera->SetParallelProjection(pose.parallel);
  camera->SetParallelScale(pose.parallel_scale);
  camera->SetWindowCenter(pose.window_center.x(), pose.window_center.y());
  camera->OrthogonalizeViewUp();
}

nlohmann::json to_json(const CameraPose& p) {
  auto array = [](const auto& v) {
    nlohmann::json a = nlohmann::json::array();
    for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v[i]);
    return a;
  };
  return {{"position", array(p.position)},
          {"focal_point", array(p.focal_point)},
          {"view_up", array(p.view_up)},
          {"view_angle", p.view_angle},
          {"parallel", p.parallel},
          {"parallel_scale", p.parallel_scale},
          {"window_center", array(p.window_center)}};
}

CameraPose camera_pose_from_json(const nlohmann::json& json, const std::string& source) {
  if (!json.is_object())
    throw InputError(source + ": expected a JSON object with the camera's keys");
  for (const char* key : {"position", "focal_point", "view_up", "view_angle", "parallel",
                          "parallel_scale", "window_center"})
    if (!json.contains(key)) throw InputError(source + ": $." + key + ": missing");
  CameraPose p;
  p.position = vector3(json, "position", source);
  p.focal_point = vector3(json, "focal_point", source);
  p.view_up = vector3(json, "view_up", source);
  if (!json["view_angle"].is_number() ||
      !(json["view_angle"].get<double>() > 0 && json["view_angle"].get<double>() < 180))
    throw InputError(source + ": $.view_angle: expected degrees between 0 and 180");
  p.view_angle = json["view_angle"].get<double>();
  if (!json["parallel"].is_boolean())
    throw InputError(source + ": $.parallel: expected true or false");
  p.parallel = json["parallel"].get<bool>();
  if (!json["parallel_scale"].is_number() || !(json["parallel_scale"].get<double>() > 0))
    throw InputError(source + ": $.parallel_scale: expected a positive number");
  p.parallel_scale = json["parallel_scale"].get<double>();
  const auto& wc = json["window_center"];
  if (!wc.is_array() || wc.size() != 2 || !wc[0].is_number() || !wc[1].is_number())
    throw InputError(source + ": $.window_center: expected an array of 2 numbers");
  p.window_center = {wc[0].get<double>(), wc[1].get<double>()};
  if ((p.position - p.focal_point).norm() == 0)
    throw InputError(source + ": $.position: the camera sits on its focal point");
  if (p.view_up.norm() == 0) throw InputError(source + ": $.view_up: must not be zero");
  return p;
}

void save_camera(const CameraPose& pose, const std::string& path) {
  const std::filesystem::path target(path);
  OutputSet out(target.has_parent_path() ? target.parent_path().string() : ".");
  out.write_text(target.filename().string(), to_json(pose).dump(2) + "\n");
  out.commit();
}

CameraPose load_camera(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot read the camera file");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path + ": not JSON (" + e.what() + ")");
  }
  return camera_pose_from_json(json, path);
}

}  // namespace sdog::vis
