#pragma once
// The legends of the layers, stacked from the top of a column at the right edge of the view: a
// scalar bar for a scalar layer, a titled list of coloured squares for a categorical one. Every
// legend's title is bold at the stack's font size, and every label (a bar's ticks, a list's
// entries) regular at kLabelScale of it: the same text in every block.
#include <vtkActor2D.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkScalarsToColors.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <string>
#include <vector>

#include "geometry/mesh/dog_mesh.h"
#include "ui/vis/palette.h"

namespace sdog::vis {

/// The legend column: normalized viewport x from `left` to 0.99.
inline constexpr double kLegendColumnLeft = 0.75;
/// Labels' font size relative to the titles'.
inline constexpr double kLabelScale = 0.85;

struct LegendEntry {
  std::string label;
  Rgb colour;
};

class Legend {
 public:
  /// A scalar bar of `lut` (shared: later changes of its range show) under `title`.
  static Legend scalar_bar(const std::string& title, vtkScalarsToColors* lut);
  /// Coloured squares with labels under `title`.
  static Legend categories(const std::string& title, const std::vector<LegendEntry>& entries);

  void add_to(vtkRenderer* renderer) const;
  void remove_from(vtkRenderer* renderer) const;
  void set_visible(bool visible) const;
  bool visible() const;
  /// Height in pixels at the font size (points = pixels here).
  double height_pixels(int font) const;
  /// Width in pixels of the title at the font size (an estimate: bold sans, 0.62 em per character).
  double title_width_pixels(int font) const;
  /// Width in pixels of the widest entry, square included, at the font size (an estimate: sans,
  /// 0.55 em per character; 0 for a scalar bar).
  double entry_width_pixels(int font) const;
  /// Places the legend with its top edge at normalized viewport height `top` in the legend column
  /// of a viewport of the given size in pixels.
  void place(double top, int viewport_width, int viewport_height, int font) const;
  vtkScalarBarActor* bar() const { return bar_; }
  /// Categories: the title, and the label of each entry.
  vtkTextActor* title() const { return title_; }
  const std::vector<vtkSmartPointer<vtkTextActor>>& labels() const { return labels_; }

 private:
  vtkSmartPointer<vtkTextActor> title_;                // categories only
  std::vector<vtkSmartPointer<vtkTextActor>> labels_;  // categories only
  vtkSmartPointer<vtkPolyData> squares_;  // categories only: one coloured quad per entry
  vtkSmartPointer<vtkActor2D> squares_actor_;
  vtkSmartPointer<vtkScalarBarActor> bar_;  // scalar bars only
};

/// The patches legend's entries: one per patch ("patch 3") up to kPatchColors patches; beyond,
/// one per colour naming the patches that share it ("patches 1, 13, 25, ...").
std::vector<LegendEntry> patch_legend_entries(int patch_count);

/// The crease lines legend's entries: the four assignments ("flat, seam" when the pattern has
/// seams), "slit" when it has slits, and the crease point.
std::vector<LegendEntry> crease_legend_entries(const CreaseStitching& stitching);

/// Stacks the visible legends from the top of the column, in the order given; shrinks them
/// evenly when they do not fit the viewport's height or a title does not fit the column's width.
void stack_legends(const std::vector<const Legend*>& legends, int viewport_width,
                   int viewport_height, int font);

}  // namespace sdog::vis
