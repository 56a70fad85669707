#include "geometry/mesh/grid.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "base/errors.h"
#include "base/text_format.h"

namespace sdog {

Resolution parse_resolution(const std::string& text) {
  auto bad = [&]() {
    return UsageError("bad resolution \"" + text +
                      "\": expected X_LINESxY_LINES such as 31x21 (or one number for a square "
                      "grid), each between " +
                      std::to_string(kMinResolution) + " and " + std::to_string(kMaxResolution));
  };
  auto parse_int = [&](const std::string& s) {
    if (s.empty() || s.size() > 6) throw bad();
    for (char c : s)
      if (!std::isdigit(static_cast<unsigned char>(c))) throw bad();
    return std::stoi(s);
  };
  const auto x = text.find_first_of("xX");
  Resolution r;
  if (x == std::string::npos) {
    r.nx = r.ny = parse_int(text);
  } else {
    r.nx = parse_int(text.substr(0, x));
    r.ny = parse_int(text.substr(x + 1));
  }
  return r;
}

Resolution resolve_resolution(const std::string& text, double width, double height) {
  if (text != "auto") return parse_resolution(text);
  const int longer = 41;
  const int shorter = std::max(3, 2 * static_cast<int>(std::lround(20.0 * std::min(width, height) /
                                                                   std::max(width, height))) +
                                      1);
  return width >= height ? Resolution{longer, shorter} : Resolution{shorter, longer};
}

std::string cell_shape_warning(const Resolution& res, double width, double height) {
  if (!(width > 0 && height > 0) || res.nx < 2 || res.ny < 2) return {};
  const double cell_w = width / (res.nx - 1), cell_h = height / (res.ny - 1);
  const double aspect = std::max(cell_w, cell_h) / std::min(cell_w, cell_h);
  if (aspect < kMaxCellAspect) return {};
  // The side with more lines keeps them; the other gets lines for square cells (odd, in range).
  auto lines_for = [](int lines, double along, double across) {
    const int cells = 2 * static_cast<int>(std::lround((lines - 1) * across / along / 2));
    return std::clamp(cells + 1, kMinResolution, kMaxResolution);
  };
  const Resolution square = res.nx >= res.ny ? Resolution{res.nx, lines_for(res.nx, width, height)}
                                             : Resolution{lines_for(res.ny, height, width), res.ny};
  return "grid cells are " + format_number(std::round(aspect * 10) / 10) + " times as " +
         (cell_h > cell_w ? "tall as wide" : "wide as tall") + " (" + res.str() +
         " on a sheet of " + format_number(width) + " x " + format_number(height) +
         "): folds are smoothest on nearly square cells, which " + square.str() + " gives";
}

void check_resolution(const Resolution& res, bool need_coarse) {
  for (int v : {res.nx, res.ny}) {
    if (v < kMinResolution)
      throw UsageError("resolution " + res.str() + " is too low: each direction needs at least " +
                       std::to_string(kMinResolution) + " grid lines");
    if (v > kMaxResolution)
      throw UsageError("resolution " + res.str() + " is too high: at most " +
                       std::to_string(kMaxResolution) + " grid lines per direction");
  }
  if (need_coarse && (res.nx % 2 == 0 || res.ny % 2 == 0))
    throw UsageError("resolution " + res.str() +
                     " has an even number of lines; the coarse mesh needs odd numbers (coarse "
                     "line j is fine line 2j), e.g. " +
                     Resolution{res.nx | 1, res.ny | 1}.str());
}

Resolution coarse_resolution(const Resolution& fine) {
  return {(fine.nx + 1) / 2, (fine.ny + 1) / 2};
}

AxisLayout layout_axis(double lo, double hi, int n, std::vector<double> pins) {
  // Coordinates equal up to rounding (within kSameCoordinate of the span) share one line.
  const double same = kSameCoordinate * (hi - lo);
  std::sort(pins.begin(), pins.end());
  std::vector<double> pin;  // distinct, ascending
  for (double p : pins)
    if (p > lo + same && p < hi - same && (pin.empty() || p - pin.back() > same)) pin.push_back(p);
  const int k = static_cast<int>(pin.size());
  if (k > n - 2)
    throw UsageError(std::to_string(n) + " grid lines cannot hold " + std::to_string(k) +
                     " junction coordinates between " + format_number(lo) + " and " +
                     format_number(hi) + " (each needs its own line); use at least " +
                     std::to_string(k + 2) + " lines");
  // Line index of pin j is i_j = s_j + j + 1 with s nondecreasing (so the indices increase): s is
  // the least-squares nondecreasing fit (pool adjacent violators) of the pins' uniform positions
  // minus j + 1, rounded and clamped so every pin keeps a line strictly inside.
  const double h = (hi - lo) / (n - 1);
  struct Block {
    double sum;
    int count;
  };
  std::vector<Block> blocks;
  for (int j = 0; j < k; ++j) {
    blocks.push_back({(pin[j] - lo) / h - (j + 1), 1});
    while (blocks.size() > 1 && blocks[blocks.size() - 2].sum / blocks[blocks.size() - 2].count >
                                    blocks.back().sum / blocks.back().count) {
      blocks[blocks.size() - 2].sum += blocks.back().sum;
      blocks[blocks.size() - 2].count += blocks.back().count;
      blocks.pop_back();
    }
  }
  AxisLayout layout;
  layout.n = n;
  layout.anchors.push_back({0, lo});
  int j = 0;
  for (const Block& b : blocks) {
    const int s = std::clamp(static_cast<int>(std::lround(b.sum / b.count)), 0, n - 2 - k);
    for (int c = 0; c < b.count; ++c, ++j) layout.anchors.push_back({s + j + 1, pin[j]});
  }
  layout.anchors.push_back({n - 1, hi});
  return layout;
}

AxisLayout refine_axis(const AxisLayout& coarse) {
  AxisLayout fine;
  fine.n = 2 * coarse.n - 1;
  for (const auto& [i, v] : coarse.anchors) fine.anchors.push_back({2 * i, v});
  return fine;
}

}  // namespace sdog
