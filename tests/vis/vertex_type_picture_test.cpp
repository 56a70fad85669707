// The fine/coarse vertex-type picture, rendered offscreen (run under xvfb-run).
#include <gtest/gtest.h>
#include <vtkImageData.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>

#include "geometry/dog_model.h"
#include "tests/test_support.h"
#include "tests/vis/image_compare.h"
#include "ui/vis/palette.h"
#include "ui/vis/vertex_type_picture.h"

namespace sdog {
namespace {

using test::pixels_near;

TEST(VertexTypePicture, ShowsEveryVertexTypeAndMatchesBaseline) {
  const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {21, 21});
  ASSERT_GT(m.map.coarse_only_count, 0);
  const std::string path = test::temp_dir("picture") + "/vertex_types.png";
  vis::render_vertex_types(m, path, {800, 400});
  ASSERT_TRUE(std::filesystem::exists(path));
  auto img = test::read_png(path);
  int dims[3];
  img->GetDimensions(dims);
  EXPECT_EQ(dims[0], 800);
  EXPECT_EQ(dims[1], 400);
  for (VertexType t : {VertexType::Link, VertexType::I, VertexType::X, VertexType::CoarseOnly})
    EXPECT_GT(pixels_near(img, vis::vertex_type_color(t)), 20) << to_string(t);
  EXPECT_GT(pixels_near(img, vis::kCreasePointColor), 20);
  const std::string msg = test::compare_with_baseline(path, "vertex_types_four_corner_arcs");
  EXPECT_TRUE(msg.empty()) << msg;
}

}  // namespace
}  // namespace sdog
