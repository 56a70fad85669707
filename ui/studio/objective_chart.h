#pragma once
// A live chart of the solver's iterations, drawn with QPainter: above, log10 of each objective term
// (unweighted sums of squares, Diagnostics::terms) and of the DOG residual; below, the time per
// iteration in milliseconds; marks (a mode switch, the end of the scenario, done) as labelled
// vertical lines. Keeps the last kMaxIterations iterations.
#include <QString>
#include <QWidget>
#include <array>
#include <deque>
#include <functional>

#include "solver/run/run.h"

class QPainter;
class QRectF;

namespace sdog::studio {

class ObjectiveChart : public QWidget {
  Q_OBJECT

 public:
  static constexpr int kMaxIterations = 400;
  explicit ObjectiveChart(QWidget* parent = nullptr);
  void add(const IterationReport& report);
  /// A vertical line at `iteration` labelled `label` (dropped with the iterations it lies before).
  void add_mark(int iteration, const QString& label);
  void clear();
  int point_count() const { return static_cast<int>(points_.size()); }
  struct Mark {
    int iteration;
    QString label;
  };
  const std::deque<Mark>& marks() const { return marks_; }
  QSize sizeHint() const override { return {360, 320}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  /// Marks: a dotted line through both boxes, the label at its top (staggered when they crowd).
  void draw_marks(QPainter& painter, const QRectF& area, const QRectF& top, const QRectF& bottom,
                  const std::function<double(int)>& x_of) const;
  struct Point {
    int iteration;
    std::array<double, kTermCount + 1> log_values;  // the terms, then the DOG residual
    double ms;
  };
  /// The series with a value above the floor somewhere (terms in use), and their range of log
  /// values [lo, hi].
  std::vector<int> used_series(double& lo, double& hi) const;
  std::deque<Point> points_;
  std::deque<Mark> marks_;
};

}  // namespace sdog::studio
