// The studio's selection and what a click picks (ui/control/selection.h, screen_pick.h), on
// display coordinates made up for the test: no window, no camera.
#include "ui/control/selection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/ui/vis/scene_fixture.h"
#include "ui/control/screen_pick.h"

namespace sdog::control {
namespace {

// Every row far from the clicks of the tests (display coordinates 1000 + row).
Eigen::MatrixX3d far_rows(int rows) {
  Eigen::MatrixX3d display(rows, 3);
  for (int i = 0; i < rows; ++i) display.row(i) << 1000 + i, 1000 + i, 0.5;
  return display;
}

TEST(ScreenPick, TheNearestWithinReachAndTheFrontOneOfAPlace) {
  Eigen::MatrixX3d display(4, 3);
  display << 10, 10, 0.5,  //
      20, 10, 0.5,         //
      20.5, 10, 0.2,       // within a pixel of row 1 and in front of it
      std::numeric_limits<double>::quiet_NaN(), 0, 0;
  EXPECT_EQ(nearest_on_screen(display, 11, 10, 5), 0);
  EXPECT_EQ(nearest_on_screen(display, 19, 10, 5), 2) << "the front one of the same place";
  EXPECT_EQ(nearest_on_screen(display, 40, 10, 5), -1) << "none within reach";
  EXPECT_EQ(nearest_on_screen(display.bottomRows(1), 0, 0, 100), -1) << "behind the camera";
  EXPECT_EQ(inside_rectangle(display, 25, 15, 15, 5), (std::vector<int>{1, 2}))
      << "any two corners";
}

TEST(Selection, AddsEachVertexOnceAndSwitchesBetweenVerticesAndCreases) {
  Selection s;
  s.select_vertices({3});
  EXPECT_EQ(s.vertex(), 3);
  s.select_vertices({5, 3, 5}, true);
  EXPECT_EQ(s.vertices(), (std::vector<int>{3, 5}));
  EXPECT_EQ(s.vertex(), -1) << "several vertices: no single one";
  s.select_creases({1, 7, 1, -1}, 4);
  EXPECT_EQ(s.creases(), (std::vector<int>{1})) << "creases that exist, each once";
  EXPECT_TRUE(s.vertices().empty()) << "picking creases drops the vertices";
  s.select_creases({2}, 4, true);
  EXPECT_EQ(s.creases(), (std::vector<int>{1, 2}));
  s.select_vertices({9});
  EXPECT_TRUE(s.creases().empty()) << "picking a vertex drops the creases";
  s.clear();
  EXPECT_TRUE(s.vertices().empty());
  EXPECT_EQ(s.picked_crease_point(), -1);
}

TEST(Selection, AClickPicksTheCreaseThroughTheNearestCreasePointElseTheNearestVertex) {
  const DogMesh& fine = test::arcs_model().fine;
  const auto& curve = fine.stitching.curves.at(1);
  const int point = curve.points.at(curve.points.size() / 2);
  Eigen::MatrixX3d crease_points = far_rows(static_cast<int>(fine.stitching.points.size()));
  crease_points.row(point) << 100, 100, 0.5;
  Eigen::MatrixX3d vertices = far_rows(fine.vertex_count());
  vertices.row(17) << 300, 300, 0.5;

  const ClickPick crease = pick_at(fine, crease_points, vertices, 105, 100);
  EXPECT_EQ(crease.crease, 1);
  EXPECT_EQ(crease.crease_point, point);
  EXPECT_EQ(crease.vertex, -1);
  EXPECT_NE(crease.message.find("crease 1 picked at crease point " + std::to_string(point)),
            std::string::npos);
  Selection s;
  s.apply(crease, static_cast<int>(fine.stitching.curves.size()));
  EXPECT_EQ(s.creases(), (std::vector<int>{1}));
  EXPECT_EQ(s.picked_crease_point(), point);

  EXPECT_EQ(pick_at(fine, crease_points, vertices, 110, 100).crease, -1)
      << "10 pixels: beyond the crease reach";
  const ClickPick vertex = pick_at(fine, Eigen::MatrixX3d(0, 3), vertices, 305, 300);
  EXPECT_EQ(vertex.vertex, 17) << "the crease layer off: vertices only";
  EXPECT_EQ(vertex.message, "vertex 17 picked (Edit > Make handle: H)");
  s.apply(vertex, static_cast<int>(fine.stitching.curves.size()));
  EXPECT_EQ(s.vertex(), 17);
  EXPECT_TRUE(s.creases().empty());
  const ClickPick nothing = pick_at(fine, Eigen::MatrixX3d(0, 3), vertices, 320, 300);
  EXPECT_EQ(nothing.vertex, -1);
  EXPECT_EQ(nothing.message, "no vertex within 12 pixels of the click");
}

}  // namespace
}  // namespace sdog::control
