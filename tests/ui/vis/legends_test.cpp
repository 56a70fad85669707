// Legends stacked in their column: shrunk to the viewport's height when there are many, and to
// the column's width when a title or an entry would run past the viewport's edge; the same text
// sizes in every block; a readable patches legend for many patches; side-by-side titles that do
// not run into each other.
#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkLookupTable.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>

#include <set>

#include "tests/ui/vis/scene_fixture.h"
#include "ui/vis/offscreen.h"
#include "ui/vis/scene.h"

#include "ui/vis/legends.h"

namespace sdog::vis {
namespace {

struct Legends : ::testing::Test {
  vtkSmartPointer<vtkLookupTable> lut = vtkSmartPointer<vtkLookupTable>::New();
  Legend bar = Legend::scalar_bar("DOG residual (log10)", lut);
  Legend types =
      Legend::categories("vertex type", {{"link", {0, 1, 0}}, {"crease point", {1, 0, 1}}});
  int title_font() const { return bar.bar()->GetTitleTextProperty()->GetFontSize(); }
};

TEST_F(Legends, KeepTheirFontWhenThereIsRoom) {
  stack_legends({&bar, &types}, 1600, 1000, 20);
  EXPECT_EQ(title_font(), 20);
}

TEST_F(Legends, ShrinkSoThatTheWidestTitleFitsTheColumn) {
  const int width = 500;  // column: a quarter of it, 120 pixels
  stack_legends({&bar, &types}, width, 1000, 20);
  const int f = title_font();
  EXPECT_LT(f, 20);
  EXPECT_LE(bar.title_width_pixels(f), (0.99 - kLegendColumnLeft) * width);
  EXPECT_GT(bar.title_width_pixels(f + 1),
            (0.99 - kLegendColumnLeft) * width);  // no smaller than needed
}

TEST_F(Legends, ShrinkToTheViewportHeight) {
  stack_legends({&bar, &types}, 1600, 200, 20);
  const int f = title_font();
  EXPECT_LT(f, 20);
  EXPECT_LE(bar.height_pixels(f) + types.height_pixels(f) + 1.6 * f, 0.95 * 200);
}

TEST_F(Legends, EveryBlockHasTheSameTitleAndLabelSizes) {
  Legend handles =
      Legend::categories("constraints", {{"handle", {1, 0.5, 0}}, {"target", {0, 0, 1}}});
  for (const int width : {1600, 500}) {
    stack_legends({&bar, &types, &handles}, width, 1000, 20);
    const int title = title_font(), label = bar.bar()->GetLabelTextProperty()->GetFontSize();
    EXPECT_EQ(label, std::lround(kLabelScale * title));
    for (const Legend* l : {&types, &handles}) {
      EXPECT_EQ(l->title()->GetTextProperty()->GetFontSize(), title);
      EXPECT_TRUE(l->title()->GetTextProperty()->GetBold());
      for (vtkTextActor* entry : l->labels()) {
        EXPECT_EQ(entry->GetTextProperty()->GetFontSize(), label) << entry->GetInput();
        EXPECT_FALSE(entry->GetTextProperty()->GetBold());
      }
    }
  }
}

TEST_F(Legends, ShrinkSoThatTheWidestEntryFitsTheColumn) {
  Legend wide =
      Legend::categories("x", {{"an entry far wider than the column of legends", {1, 0, 0}}});
  const int width = 1000;
  stack_legends({&wide}, width, 1000, 20);
  const int f = wide.title()->GetTextProperty()->GetFontSize();
  EXPECT_LT(f, 20);
  EXPECT_LE(wide.entry_width_pixels(f), (0.99 - kLegendColumnLeft) * width);
}

TEST(PatchLegend, OneEntryPerPatchUpToTheColoursThenOnePerColour) {
  const auto few = patch_legend_entries(5);
  ASSERT_EQ(few.size(), 5u);
  EXPECT_EQ(few[4].label, "patch 4");
  const auto many = patch_legend_entries(41);
  ASSERT_EQ(many.size(), size_t(kPatchColours));
  EXPECT_EQ(kPatchColours, 12);
  EXPECT_EQ(many[0].label, "patches 0, 12, 24, ...");  // 36 shares it too
  EXPECT_EQ(many[5].label, "patches 5, 17, 29");
  EXPECT_EQ(patch_legend_entries(21)[9].label, "patch 9");  // the only one of its colour
  std::set<Rgb> colours;
  for (int k = 0; k < kPatchColours; ++k) {
    EXPECT_EQ(many[k].colour, patch_colour(k));
    colours.insert(patch_colour(k));
  }
  EXPECT_EQ(colours.size(), size_t(kPatchColours));  // all distinct
  EXPECT_EQ(patch_colour(kPatchColours), patch_colour(0));
}

TEST(PanelTitles, DoNotOverlapInANarrowSideBySideView) {
  if (!display_unavailable().empty()) GTEST_SKIP() << display_unavailable();
  for (const ImageSize size : {ImageSize{1600, 800}, ImageSize{640, 360}, ImageSize{400, 300}}) {
    auto window = offscreen_window(size);
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    window->AddRenderer(renderer);
    SceneOptions options{View::kSideBySide, false, 20};
    Scene scene(test::arcs_model(), renderer, options);
    scene.reset_camera();
    window->Render();
    const auto [fine, coarse] = scene.panel_titles();
    ASSERT_TRUE(fine->GetVisibility() && coarse->GetVisibility());
    double a[4], b[4];  // xmin, xmax, ymin, ymax in pixels, from the text's anchor
    fine->GetBoundingBox(renderer, a);
    coarse->GetBoundingBox(renderer, b);
    const double fine_x = fine->GetPositionCoordinate()->GetComputedDoubleDisplayValue(renderer)[0];
    const double coarse_x =
        coarse->GetPositionCoordinate()->GetComputedDoubleDisplayValue(renderer)[0];
    EXPECT_GT(a[1] - a[0], 10);
    EXPECT_LT(fine_x + a[1], coarse_x + b[0])
        << size.width << "x" << size.height << ": the fine title ends at " << fine_x + a[1]
        << ", the coarse one starts at " << coarse_x + b[0];
    if (size.width == 1600) {
      EXPECT_EQ(fine->GetTextProperty()->GetFontSize(), 20);  // room: not shrunk
    }
  }
}

// The crease legend names slits and seams only for a pattern that has them.
TEST(CreaseLegend, NamesSlitsAndSeamsWhereThePatternHasThem) {
  auto labels = [](const std::string& file) {
    const DogModel m = build_dog_model(read_crease_pattern(test::dataset(file)), {21, 21});
    std::set<std::string> out;
    for (const LegendEntry& e : crease_legend_entries(m.fine.stitching)) out.insert(e.label);
    return out;
  };
  const std::set<std::string> slits = labels("slits_and_tab.svg");
  EXPECT_TRUE(slits.count("slit") && slits.count("flat, seam"));
  const std::set<std::string> plain = labels("curved_pleats.svg");
  EXPECT_TRUE(plain.count("flat") && !plain.count("slit") && !plain.count("flat, seam"));
}

}  // namespace
}  // namespace sdog::vis
