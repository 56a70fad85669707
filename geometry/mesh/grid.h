#pragma once
// The orthogonal grid: x_res vertical and y_res horizontal grid lines over the sheet's bounding
// box. Without pins, x_i = xmin + i (xmax - xmin) / (x_res - 1). Each pinned coordinate (a
// junction's x or y) takes the line nearest to it, lines keep their order and count, and the lines
// between two pinned ones are spaced uniformly again.
//
// Nesting: the coarse grid of an odd resolution n is the grid of resolution (n + 1) / 2, and the
// fine grid is the coarse one with a line added half way between every two neighbours. So for odd
// resolutions pins sit on even fine lines, coarse line j is fine line 2j, and coarse crease points
// are fine crease points.
#include <string>
#include <utility>
#include <vector>

namespace sdog {

struct Resolution {
  int nx = 0, ny = 0;  ///< numbers of grid lines (vertices), not cells
  std::string str() const { return std::to_string(nx) + "x" + std::to_string(ny); }
  bool operator==(const Resolution& o) const { return nx == o.nx && ny == o.ny; }
};

constexpr int kMinResolution = 3;
constexpr int kMaxResolution = 2001;

/// Parses "31x21" (or "41" for 41x41). Throws UsageError with the accepted form and range.
Resolution parse_resolution(const std::string& text);

/// `text` parsed, or for "auto" the default resolution of a sheet `width` x `height`: 41 lines
/// along the longer side, the other side in proportion (odd, at least 3).
Resolution resolve_resolution(const std::string& text, double width, double height);

/// Cells at least this many times as long one way as the other get a warning.
constexpr double kMaxCellAspect = 1.5;

/// Empty, or a warning when the cells of `res` over a sheet `width` x `height` are at least
/// kMaxCellAspect times as long one way as the other, naming the resolution (odd, same lines
/// along the side with more) whose cells are nearly square.
std::string cell_shape_warning(const Resolution& res, double width, double height);

/// Throws UsageError unless 3 <= nx, ny <= 2001, and both are odd when `need_coarse`.
void check_resolution(const Resolution& res, bool need_coarse);

/// The coarse resolution ((nx + 1) / 2, (ny + 1) / 2) of an odd fine resolution.
Resolution coarse_resolution(const Resolution& fine);

/// Where the lines of one axis go: `n` lines; line `anchors[k].first` sits at
/// `anchors[k].second`; lines between two anchors are spaced uniformly. The first and last line
/// are always anchors (the sheet's extent).
struct AxisLayout {
  int n = 0;
  std::vector<std::pair<int, double>> anchors;
};

/// Pins closer than this share of the span are one coordinate (rounding apart).
constexpr double kSameCoordinate = 1e-9;
/// Places `n` lines over [lo, hi] with every pin (strictly inside) on its own line, as near to
/// its uniform position as the order of the pins allows. Throws UsageError when more distinct
/// pins than the n - 2 inner lines.
AxisLayout layout_axis(double lo, double hi, int n, std::vector<double> pins);

/// The layout with a line added half way between every two neighbouring lines (2n - 1 lines).
AxisLayout refine_axis(const AxisLayout& coarse);

}  // namespace sdog
