// Cameras (camera.h): the default views and camera poses saved as JSON.
#include <gtest/gtest.h>

#include <vtkRenderer.h>

#include <Eigen/Geometry>
#include <cmath>

#include "base/errors.h"
#include "tests/ui/vis/scene_fixture.h"
#include "ui/vis/camera.h"

namespace sdog {
namespace {

TEST(Camera, DefaultCamerasAreFixedFunctionsOfTheBounds) {
  const vis::Bounds b{0, 20, 0, 10, 0, 0};
  const vis::CameraPose top = vis::top_view_camera(b, 2.0);
  EXPECT_TRUE(top.parallel);
  EXPECT_EQ(top.focal_point, Eigen::Vector3d(10, 5, 0));
  EXPECT_EQ(top.view_up, Eigen::Vector3d(0, 1, 0));
  // 20 units wide in 90% of the drawing area (0.75 of a viewport twice as wide as high).
  EXPECT_NEAR(top.parallel_scale, 20 / (2 * 0.9 * 2.0 * 0.75), 1e-12);
  const vis::CameraPose d3 = vis::three_d_camera(b, 2.0);
  EXPECT_FALSE(d3.parallel);
  const Eigen::Vector3d dir = (d3.position - d3.focal_point).normalized();
  EXPECT_NEAR((dir - Eigen::Vector3d(0.9, -1.2, 1).normalized()).norm(), 0, 1e-12);
}

// Projects p with the pose's perspective camera to viewport units [-1, 1]; the window centre w
// moves the image by -w (a focal point at w = (0.25, 0) shows at x = -0.25).
Eigen::Vector2d project(const vis::CameraPose& pose, const Eigen::Vector3d& p, double aspect) {
  const Eigen::Vector3d back = (pose.position - pose.focal_point).normalized();
  const Eigen::Vector3d right = pose.view_up.cross(back).normalized();
  const Eigen::Vector3d up = back.cross(right);
  const Eigen::Vector3d rel = p - pose.position;
  const double depth = -rel.dot(back), t = std::tan(0.5 * pose.view_angle * M_PI / 180);
  return {rel.dot(right) / (depth * t * aspect) - pose.window_center.x(),
          rel.dot(up) / (depth * t) - pose.window_center.y()};
}

TEST(Camera, TheThreeDCameraFitsEveryCornerTightly) {
  const vis::Bounds b{0, 40, 0, 25, -3, 12};
  for (bool legends : {true, false}) {
    const double aspect = 1.6;
    const vis::CameraPose pose = vis::three_d_camera(b, aspect, legends);
    const double right_edge =
        legends ? 2 * 0.75 - 1 : 1;  // the legend column starts at 0.75 of the width
    double widest = 0, tallest = 0;
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector2d q =
          project(pose, {b[k & 1], b[2 + ((k >> 1) & 1)], b[4 + ((k >> 2) & 1)]}, aspect);
      EXPECT_GE(q.x(), -1) << k;
      EXPECT_LE(q.x(), right_edge + 1e-9) << k;
      EXPECT_GE(q.y(), -1) << k;
      EXPECT_LE(q.y(), 1) << k;
      widest = std::max(widest, std::abs(q.x() + pose.window_center.x()));
      tallest = std::max(tallest, std::abs(q.y()));
    }
    // Tight: some corner reaches within 10% of the edge of the drawing area.
    EXPECT_GT(std::max(widest / (0.5 * (right_edge + 1)), tallest), 0.9);
  }
}

TEST(Camera, SavedCameraLoadsBackAndBadFilesSayWhy) {
  const std::string dir = test::temp_dir("camera");
  vis::CameraPose pose = vis::three_d_camera({0, 20, 0, 10, 0, 3}, 1.5);
  pose.view_angle = 25;
  vis::save_camera(pose, dir + "/camera.json");
  const vis::CameraPose back = vis::load_camera(dir + "/camera.json");
  EXPECT_EQ(back.position, pose.position);
  EXPECT_EQ(back.focal_point, pose.focal_point);
  EXPECT_EQ(back.view_up, pose.view_up);
  EXPECT_EQ(back.view_angle, 25);
  EXPECT_EQ(back.parallel, pose.parallel);
  EXPECT_EQ(back.window_center, pose.window_center);
  // Applied to a VTK camera and read back.
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  vis::apply_camera_pose(back, renderer->GetActiveCamera());
  const vis::CameraPose read = vis::camera_pose(renderer->GetActiveCamera());
  EXPECT_NEAR((read.position - pose.position).norm(), 0, 1e-9);
  EXPECT_NEAR(read.window_center.x(), pose.window_center.x(), 1e-12);

  const std::string bad = test::write_file(dir, "bad.json", R"({"position": [0, 0, 1]})");
  try {
    vis::load_camera(bad);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(bad + ": $.focal_point: missing"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(vis::load_camera(test::write_file(dir, "text.json", "not json")), InputError);
  EXPECT_THROW(vis::load_camera(dir + "/missing.json"), InputError);
  EXPECT_THROW(vis::save_camera(pose, test::write_file(dir, "file", "x") + "/sub/camera.json"),
               OutputError);
}

}  // namespace
}  // namespace sdog
