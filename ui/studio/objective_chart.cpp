#include "ui/studio/objective_chart.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "solver/problem/dog_problem.h"
#include "ui/vis/palette.h"

namespace sdog::studio {
namespace {

constexpr double kLogFloor = -16;  // log10 of values at or below 0 (unused terms)

// The palette's colours, dashed once they repeat (nine series, seven colours).
QPen series_pen(int index) {
  const vis::Rgb c = vis::series_colour(index);
  return QPen(QColor::fromRgbF(c[0], c[1], c[2]), 1.6, index >= 7 ? Qt::DashLine : Qt::SolidLine);
}

}  // namespace

ObjectiveChart::ObjectiveChart(QWidget* parent) : QWidget(parent) {
  setMinimumSize(200, 160);
  setToolTip(
      "Objective terms (log10 of the unweighted sums of squares), the largest DOG constraint "
      "residual "
      "and the time per iteration, for the last iterations");
}

void ObjectiveChart::add(const IterationReport& report) {
  Point p;
  p.iteration = report.iteration;
  auto log_of = [](double v) { return v > 0 ? std::max(kLogFloor, std::log10(v)) : kLogFloor; };
  for (int t = 0; t < kTermCount; ++t) p.log_values[t] = log_of(report.diagnostics.terms[t]);
  p.log_values[kTermCount] = log_of(report.diagnostics.dog_max);
  p.ms = report.iteration_ms;
  points_.push_back(p);
  while (static_cast<int>(points_.size()) > kMaxIterations) points_.pop_front();
  while (!marks_.empty() && marks_.front().iteration < points_.front().iteration)
    marks_.pop_front();
  update();
}

void ObjectiveChart::add_mark(int iteration, const QString& label) {
  marks_.push_back({iteration, label});
  update();
}

void ObjectiveChart::clear() {
  points_.clear();
  marks_.clear();
  update();
}

void ObjectiveChart::draw_marks(QPainter& painter, const QRectF& area, const QRectF& top,
                                const QRectF& bottom,
                                const std::function<double(int)>& x_of) const {
  // Marks: a dotted line through both boxes, the label at its top (staggered when they crowd).
  double last_label_end = -1e9;
  int row = 0;
  for (const Mark& m : marks_) {
    const double x = x_of(m.iteration);
    if (x < area.left() - 0.5 || x > area.right() + 0.5) continue;
    painter.setPen(QPen(QColor(90, 90, 90), 1.0, Qt::DotLine));
    painter.drawLine(QPointF(x, top.top()), QPointF(x, bottom.bottom()));
    row = x < last_label_end ? row + 1 : 0;
    const double text_width = painter.fontMetrics().horizontalAdvance(m.label);
    painter.setPen(QColor(60, 60, 60));
    painter.drawText(
        QPointF(std::min(x + 3, area.right() - text_width), top.top() + 12 + 13 * (row % 3)),
        m.label);
    last_label_end = x + 3 + text_width;
  }
}

std::vector<int> ObjectiveChart::used_series(double& lo, double& hi) const {
  std::vector<int> used;
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (int s = 0; s <= kTermCount; ++s) {
    bool any = false;
    for (const Point& p : points_)
      if (p.log_values[s] > kLogFloor) {
        any = true;
        lo = std::min(lo, p.log_values[s]);
        hi = std::max(hi, p.log_values[s]);
      }
    if (any) used.push_back(s);
  }
  return used;
}

void ObjectiveChart::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), Qt::white);
  painter.setRenderHint(QPainter::Antialiasing);
  const int legend_width = 124, margin = 6, gap = 18;
  const QRectF area(margin + 34, margin + 14, width() - legend_width - 2 * margin - 34,
                    height() - 2 * margin - gap - 28);
  if (area.width() < 20 || area.height() < 40) return;
  const QRectF top(area.left(), area.top(), area.width(), area.height() * 0.65);
  const QRectF bottom(area.left(), top.bottom() + gap, area.width(),
                      area.height() * 0.35 - gap / 2.0);
  painter.setPen(Qt::black);
  painter.drawText(QPointF(top.left(), top.top() - 3), "log10 objective terms, DOG residual");
  painter.drawText(QPointF(bottom.left(), bottom.top() - 3), "ms per iteration");
  painter.setPen(Qt::gray);
  painter.drawRect(top);
  painter.drawRect(bottom);
  if (points_.empty()) return;

  const double first = points_.front().iteration,
               last = std::max(first + 1.0, double(points_.back().iteration));
  auto x_of = [&](int iteration) {
    return area.left() + (iteration - first) / (last - first) * area.width();
  };
  // Draws one series (value_of(point), NaN = left out) in `box` scaled to [lo, hi].
  auto draw = [&](const QRectF& box, double lo, double hi, const QPen& pen,
                  const std::function<double(const Point&)>& value_of) {
    QPainterPath path;
    bool started = false;
    for (const Point& p : points_) {
      const double v = value_of(p);
      if (!std::isfinite(v)) continue;
      const QPointF q(x_of(p.iteration),
                      box.bottom() - (v - lo) / std::max(hi - lo, 1e-12) * box.height());
      if (started)
        path.lineTo(q);
      else
        path.moveTo(q);
      started = true;
    }
    painter.setPen(pen);
    painter.drawPath(path);
  };

  double lo = 0, hi = 0;
  const std::vector<int> used = used_series(lo, hi);
  int legend_row = 0;
  for (int s : used) {
    draw(top, std::floor(lo), std::ceil(hi), series_pen(s), [s](const Point& p) {
      return p.log_values[s] > kLogFloor ? p.log_values[s]
                                         : std::numeric_limits<double>::quiet_NaN();
    });
    const double y = top.top() + 12 + 14 * legend_row++;
    painter.setPen(series_pen(s));
    painter.drawLine(QPointF(area.right() + 6, y - 4), QPointF(area.right() + 20, y - 4));
    painter.setPen(series_pen(s).color());
    painter.drawText(QPointF(area.right() + 24, y), s < kTermCount ? term_name(s) : "dog residual");
  }
  draw_marks(painter, area, top, bottom, x_of);
  painter.setPen(Qt::black);
  if (!used.empty()) {
    painter.drawText(QPointF(margin, top.top() + 10), QString::number(std::ceil(hi)));
    painter.drawText(QPointF(margin, top.bottom()), QString::number(std::floor(lo)));
  }
  double ms_max = 0;
  for (const Point& p : points_) ms_max = std::max(ms_max, p.ms);
  draw(bottom, 0, std::max(ms_max, 1e-3), QPen(Qt::black, 1.6),
       [](const Point& p) { return p.ms; });
  painter.setPen(Qt::black);
  painter.drawText(QPointF(margin, bottom.top() + 10), QString::number(ms_max, 'g', 3));
  painter.drawText(QPointF(margin, bottom.bottom()), "0");
  painter.drawText(
      QPointF(area.left(), bottom.bottom() + 16),
      QString("iterations %1 to %2").arg(points_.front().iteration).arg(points_.back().iteration));
}

}  // namespace sdog::studio
