// sdog render through the executable: overlays after a run, the PNG it writes, errors and exit
// codes.
#include <gtest/gtest.h>
#include <vtkImageData.h>

#include <filesystem>

#include "tests/app/run_sdog.h"
#include "tests/ui/vis/image_compare.h"
#include "ui/vis/palette.h"

namespace sdog {
namespace {

const std::string kArcs = std::string(SDOG_DATASETS_DIR) + "/four_corner_arcs.svg";

TEST(RenderCommand, DrawsAnOverlayAfterARun) {
  const std::string dir = test::temp_dir("render_run");
  const auto r = test::run_sdog(
      "render " + kArcs + " --res 21x21 --iters 10 --overlay dog-residual,handles --view 3d " +
      "--size 480x300 --out " + dir + "/residual.png");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + dir + "/residual.png"), std::string::npos) << r.out;
  auto img = test::read_png(dir + "/residual.png");
  int dims[3];
  img->GetDimensions(dims);
  EXPECT_EQ(dims[0], 480);
  EXPECT_EQ(dims[1], 300);
  EXPECT_GT(test::pixels_near(img, vis::kHandleColour), 5);
}

TEST(RenderCommand, DefaultIsTheVertexTypePicture) {
  const std::string dir = test::temp_dir("render_default");
  const auto r =
      test::run_sdog("render " + kArcs + " --res 21x21 --size 480x240 --out " + dir + "/types.png");
  ASSERT_EQ(r.code, 0) << r.err;
  // Nothing but what sdog says: no VTK log lines.
  EXPECT_EQ(r.err.find("ERR|"), std::string::npos) << r.err;
  auto img = test::read_png(dir + "/types.png");
  EXPECT_GT(test::pixels_near(img, vis::vertex_type_colour(VertexType::kCoarseOnly)), 5);
}

TEST(RenderCommand, UnknownOverlayListsTheKnownOnes) {
  const std::string dir = test::temp_dir("render_unknown");
  const auto r = test::run_sdog("render " + kArcs + " --overlay vertex-types,residuals --out " +
                                dir + "/x.png");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  for (const char* s : {"unknown overlay 'residuals'", "vertex-types", "dog-residual", "wireframe"})
    EXPECT_NE(r.err.find(s), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(RenderCommand, UsageErrorsExitWith2) {
  const std::string dir = test::temp_dir("render_usage");
  for (const std::string args :
       {"--overlay bending,patches", "--view top", "--iters 5 --mode fastest", "--mode coarse",
        "--size 10x10", "--iters 5 --scenario nothing"}) {
    const auto r =
        test::run_sdog("render " + kArcs + " --res 21x21 " + args + " --out " + dir + "/x.png");
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1) << args << ": " << r.err;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(RenderCommand, UnwritableOutputExitsWith1BeforeTheRun) {
  const std::string dir = test::temp_dir("render_unwritable");
  test::write_file(dir, "file", "x");
  const auto r = test::run_sdog("render " + kArcs + " --res 21x21 --iters 100000 --out " + dir +
                                "/file/x.png");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find(dir + "/file"), std::string::npos) << r.err;
}

TEST(RenderCommand, MissingPatternExitsWith1) {
  const std::string dir = test::temp_dir("render_missing");
  const auto r = test::run_sdog("render " + dir + "/none.svg --out " + dir + "/x.png");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace sdog
