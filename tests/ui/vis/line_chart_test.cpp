// Line charts rendered offscreen (run under xvfb-run): size, the series' colours, errors.
#include <gtest/gtest.h>
#include <vtkImageData.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "base/errors.h"
#include "tests/test_support.h"
#include "tests/ui/vis/image_compare.h"
#include "ui/vis/line_chart.h"
#include "ui/vis/vtk_meshes.h"

namespace sdog {
namespace {

using test::pixels_near;

int distinct_colours(vtkImageData* img) {
  int dims[3];
  img->GetDimensions(dims);
  std::set<long> colours;
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      long key = 0;
      for (int k = 0; k < 3; ++k)
        key = 256 * key + static_cast<long>(img->GetScalarComponentAsDouble(x, y, 0, k));
      colours.insert(key);
    }
  return static_cast<int>(colours.size());
}

vis::LineChart three_lines() {
  vis::LineChart chart = vis::titled_chart("three lines", "iteration", "objective (weighted)");
  const vis::Rgb colours[] = {{0.9, 0.1, 0.1}, {0.1, 0.6, 0.1}, {0.1, 0.1, 0.9}};
  for (int s = 0; s < 3; ++s) {
    vis::ChartSeries series{"series " + std::to_string(s), {}, {}, colours[s]};
    for (int i = 1; i <= 50; ++i) {
      series.x.push_back(i);
      series.y.push_back((s + 1) * std::sqrt(i));
    }
    chart.series.push_back(series);
  }
  return chart;
}

TEST(LineChart, WritesAPngOfTheSizeWithEverySeriesColour) {
  const std::string path = test::temp_dir("line_chart") + "/chart.png";
  const vis::LineChart chart = three_lines();
  vis::render_line_chart(chart, {900, 500}, path);
  ASSERT_TRUE(std::filesystem::exists(path));
  auto img = test::read_png(path);
  int dims[3];
  img->GetDimensions(dims);
  EXPECT_EQ(dims[0], 900);
  EXPECT_EQ(dims[1], 500);
  for (const auto& s : chart.series) EXPECT_GT(pixels_near(img, *s.colour), 100) << s.name;
  EXPECT_GT(pixels_near(img, {1, 1, 1}), 900 * 500 / 2);  // white background
  EXPECT_GT(distinct_colours(img), 8);                    // lines, text, antialiased glyphs
}

TEST(LineChart, DefaultColoursComeFromThePalette) {
  const std::string path = test::temp_dir("line_chart_palette") + "/chart.png";
  vis::LineChart chart = three_lines();
  for (auto& s : chart.series) s.colour.reset();
  chart.log_y = true;
  vis::render_line_chart(chart, {640, 400}, path);
  auto img = test::read_png(path);
  for (int k = 0; k < 3; ++k) EXPECT_GT(pixels_near(img, vis::series_colour(k)), 50) << k;
}

TEST(LineChart, BadPathThrowsAndLeavesNoFile) {
  const std::string dir = test::temp_dir("line_chart_bad");
  const std::string path = dir + "/missing/chart.png";
  EXPECT_THROW(vis::render_line_chart(three_lines(), {640, 400}, path), OutputError);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(LineChart, NothingToDrawIsAnError) {
  const std::string path = test::temp_dir("line_chart_empty") + "/chart.png";
  vis::LineChart chart = vis::titled_chart("empty", "x", "y");
  chart.series.push_back({"nan", {1, 2}, {NAN, NAN}, std::nullopt});
  EXPECT_THROW(vis::render_line_chart(chart, {640, 400}, path), UsageError);
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace sdog

namespace sdog {
namespace {

// A run that failed in its first iteration leaves a series of one point: drawn as a point, not as a
// line (VTK reports an error for a line of fewer than two points).
TEST(LineChart, DrawsASeriesOfOnePointWithoutAVtkError) {
  vis::take_vtk_error();  // installs the collector, drops anything earlier
  vis::LineChart chart = three_lines();
  chart.series.push_back({"one point", {3}, {2}, vis::Rgb{0.9, 0.6, 0.0}});
  const std::string path = test::temp_dir("line_chart_one_point") + "/chart.png";
  vis::render_line_chart(chart, {900, 500}, path);
  EXPECT_EQ(vis::take_vtk_error(), "");
  EXPECT_TRUE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace sdog
