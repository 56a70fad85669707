#pragma once
// Line charts (one line per series, a legend, titled axes) rendered offscreen to PNG with VTK's
// 2D charts: the plots of `sdog compare`. Plain data in, so any caller can draw them.
#include <optional>
#include <string>
#include <vector>

#include "ui/vis/offscreen.h"
#include "ui/vis/palette.h"

namespace sdog::vis {

struct ChartSeries {
  std::string name;           ///< legend entry
  std::vector<double> x, y;   ///< same length; non-finite points are left out
  std::optional<Rgb> colour;  ///< default: series_color(index of the series)
};

struct LineChart {
  std::string title;
  std::string x_title, y_title;       ///< with units, e.g. "time per iteration (ms)"
  bool log_x = false, log_y = false;  ///< logarithmic axes (non-positive values are left out)
  std::vector<ChartSeries> series;
  double line_width = 3;
  int title_font = 30, axis_title_font = 26, label_font = 22, legend_font = 24;  ///< points
};

/// A chart with its title and axis titles (the rest at the defaults above).
LineChart titled_chart(const std::string& title, const std::string& x_title,
                       const std::string& y_title);

/// Draws the chart offscreen, the legend in the top right corner above the lines (the y axis gets
/// the room for it), linear axes with about 8 round ticks (needs an X display, see offscreen.h) and
/// writes it as PNG to `png_path`. Throws UsageError for a chart without a single drawable point or
/// series of different x and y lengths, OutputError when the file cannot be written (nothing is
/// left).
void render_line_chart(const LineChart& chart, const ImageSize& size, const std::string& png_path);

}  // namespace sdog::vis
