// Legends stacked in their column: shrunk to the viewport's height when there are many, and to
// the column's width when a title would run past the viewport's edge.
#include <gtest/gtest.h>
#include <vtkLookupTable.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>

#include "ui/vis/legends.h"

namespace sdog::vis {
namespace {

struct Legends : ::testing::Test {
  vtkSmartPointer<vtkLookupTable> lut = vtkSmartPointer<vtkLookupTable>::New();
  Legend bar = Legend::scalar_bar("DOG residual (log10)", lut);
  Legend types = Legend::categories("vertex type", {{"link", {0, 1, 0}}, {"crease point", {1, 0, 1}}});
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
  EXPECT_GT(bar.title_width_pixels(f + 1), (0.99 - kLegendColumnLeft) * width);  // no smaller than needed
}

TEST_F(Legends, ShrinkToTheViewportHeight) {
  stack_legends({&bar, &types}, 1600, 200, 20);
  const int f = title_font();
  EXPECT_LT(f, 20);
  EXPECT_LE(bar.height_pixels(f) + types.height_pixels(f) + 1.6 * f, 0.95 * 200);
}

}  // namespace
}  // namespace sdog::vis
