#include "ui/vis/line_chart.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkPlot.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "base/errors.h"

namespace sdog::vis {
namespace {

void style_text(vtkTextProperty* p, int size, bool bold = false) {
  p->SetFontSize(size);
  p->SetColor(kTextColour[0], kTextColour[1], kTextColour[2]);
  p->SetBold(bold);
}

void style_axis(vtkAxis* axis, const std::string& title, bool log, const LineChart& chart) {
  axis->SetTitle(title);
  style_text(axis->GetTitleProperties(), chart.axis_title_font, true);
  style_text(axis->GetLabelProperties(), chart.label_font);
  axis->SetLogScale(log);
}

bool drawable(double x, double y, const LineChart& chart) {
  return std::isfinite(x) && std::isfinite(y) && (!chart.log_x || x > 0) && (!chart.log_y || y > 0);
}

// The series' drawable points as a two-column table (x, name).
vtkSmartPointer<vtkTable> series_table(const ChartSeries& s, const LineChart& chart) {
  auto x = vtkSmartPointer<vtkDoubleArray>::New();
  x->SetName("x");
  auto y = vtkSmartPointer<vtkDoubleArray>::New();
  y->SetName(s.name.c_str());
  for (size_t i = 0; i < s.x.size(); ++i)
    if (drawable(s.x[i], s.y[i], chart)) {
      x->InsertNextValue(s.x[i]);
      y->InsertNextValue(s.y[i]);
    }
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(x);
  table->AddColumn(y);
  return table;
}

// Smallest and largest drawable x (or y) value.
std::array<double, 2> data_range(const LineChart& chart, bool x) {
  std::array<double, 2> r{HUGE_VAL, -HUGE_VAL};
  for (const auto& s : chart.series)
    for (size_t i = 0; i < s.x.size(); ++i)
      if (drawable(s.x[i], s.y[i], chart)) {
        const double v = x ? s.x[i] : s.y[i];
        r = {std::min(r[0], v), std::max(r[1], v)};
      }
  return r;
}

// 1, 2 or 5 times a power of ten, at least `raw`.
double round_step(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw * (1 - 1e-9)) return m * p;
  return 10 * p;
}

// Fixes the axis range to the data (from 0 for non-negative data when `from_zero`, plus `top_room`,
// a fraction of the plot left free at the top);
// linear axes get round ticks at least `spacing` pixels apart and at most 12, so that labels do not
// collide (VTK's automatic ticks ignore the label width).
void set_range(vtkAxis* axis, std::array<double, 2> r, bool log, bool from_zero, double top_room,
               double spacing, int pixels) {
  if (log) {
    r = {std::log10(r[0]), std::log10(r[1])};
  }
  double span = r[1] - r[0];
  if (!(span > 0)) span = std::max(1.0, std::abs(r[0]));
  double lo = r[0] - (log ? 0.02 * span : 0.0), hi = r[1] + 0.02 * span;
  hi += (hi - lo) * top_room / (1 - top_room);
  if (log) {
    axis->SetUnscaledRange(std::pow(10.0, lo), std::pow(10.0, hi));
    axis->SetBehavior(vtkAxis::FIXED);
    return;
  }
  if (from_zero && r[0] >= 0) lo = 0;
  if (r[1] == r[0]) {
    lo = r[0] - 0.5 * span;
    hi = r[0] + 0.5 * span;
  }
  axis->SetUnscaledRange(lo, hi);
  axis->SetBehavior(vtkAxis::FIXED);
  const int count = std::clamp(static_cast<int>(pixels / spacing), 3, 12);
  const double step = round_step((hi - lo) / count);
  auto positions = vtkSmartPointer<vtkDoubleArray>::New();
  auto labels = vtkSmartPointer<vtkStringArray>::New();
  for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step) {
    const double v = std::abs(t) < 1e-9 * step ? 0.0 : t;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    positions->InsertNextValue(v);
    labels->InsertNextValue(buf);
  }
  axis->SetCustomTickPositions(positions, labels);
}

}  // namespace

LineChart titled_chart(const std::string& title, const std::string& x_title,
                       const std::string& y_title) {
  LineChart chart;
  chart.title = title;
  chart.x_title = x_title;
  chart.y_title = y_title;
  return chart;
}

void render_line_chart(const LineChart& chart, const ImageSize& size, const std::string& png_path) {
  int points = 0;
  for (const auto& s : chart.series) {
    if (s.x.size() != s.y.size())
      throw std::logic_error("render_line_chart: series '" + s.name + "' has " +
                             std::to_string(s.x.size()) + " x and " + std::to_string(s.y.size()) +
                             " y values");
    for (size_t i = 0; i < s.x.size(); ++i) points += drawable(s.x[i], s.y[i], chart);
  }
  if (points == 0)
    throw UsageError(png_path + ": the chart '" + chart.title + "' has no point to draw");

  auto window = offscreen_window(size);
  auto view = vtkSmartPointer<vtkContextView>::New();
  view->SetRenderWindow(window);
  view->GetRenderer()->SetBackground(1, 1, 1);
  auto xy = vtkSmartPointer<vtkChartXY>::New();
  view->GetScene()->AddItem(xy);
  xy->SetTitle(chart.title);
  style_text(xy->GetTitleProperties(), chart.title_font, true);
  style_axis(xy->GetAxis(vtkAxis::BOTTOM), chart.x_title, chart.log_x, chart);
  style_axis(xy->GetAxis(vtkAxis::LEFT), chart.y_title, chart.log_y, chart);
  // The legend's height (a line per series) as a fraction of the plot area, left free above the
  // lines.
  const double plot_height = 0.75 * size.height;
  const double legend_room = std::min(
      0.5, (1.5 * chart.legend_font * chart.series.size() + 20) / std::max(1.0, plot_height));
  // Tick labels: up to 6 characters side by side on x, one text line each on y.
  set_range(xy->GetAxis(vtkAxis::BOTTOM), data_range(chart, true), chart.log_x, false, 0.0,
            5.0 * chart.label_font, size.width);
  set_range(xy->GetAxis(vtkAxis::LEFT), data_range(chart, false), chart.log_y, true, legend_room,
            3.0 * chart.label_font, size.height);
  for (size_t k = 0; k < chart.series.size(); ++k) {
    const ChartSeries& s = chart.series[k];
    const Rgb c = s.colour ? *s.colour : series_colour(static_cast<int>(k));
    vtkSmartPointer<vtkTable> table = series_table(s, chart);
    // A run that failed in its first iteration has one point: a line needs two.
    vtkPlot* line = xy->AddPlot(table->GetNumberOfRows() < 2 ? vtkChart::POINTS : vtkChart::LINE);
    line->SetInputData(table, 0, 1);
    line->SetColor(c[0], c[1], c[2]);
    line->SetWidth(static_cast<float>(chart.line_width));
    line->SetLabel(s.name);
  }
  xy->SetShowLegend(true);
  vtkChartLegend* legend = xy->GetLegend();
  style_text(legend->GetLabelProperties(), chart.legend_font);
  legend->SetSymbolWidth(3 * chart.legend_font);
  legend->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  legend->SetVerticalAlignment(vtkChartLegend::TOP);
  save_png(window, png_path);
}

}  // namespace sdog::vis
