#pragma once
// What the 3D view draws of the user's selection: the selected vertices as orange dots over the
// mesh, and the rubber band while it is spanned (a rectangle in display coordinates).
#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <Eigen/Core>
#include <vector>

namespace sdog::studio {

class SelectionMarks {
 public:
  /// Adds the (hidden) actors to `renderer`, which must outlive the marks.
  explicit SelectionMarks(vtkRenderer* renderer);
  ~SelectionMarks();
  SelectionMarks(const SelectionMarks&) = delete;
  SelectionMarks& operator=(const SelectionMarks&) = delete;

  /// Dots at the rows `selected` of `positions` (none: hidden).
  void show_points(const Eigen::MatrixX3d& positions, const std::vector<int>& selected);
  /// The band between two display positions ...
  void show_band(double x0, double y0, double x1, double y1);
  /// ... and without it.
  void hide_band();
  bool band_visible() const;
  /// The dots' data (tests).
  vtkPolyData* points() const { return points_; }

 private:
  vtkRenderer* renderer_;
  vtkSmartPointer<vtkPolyData> points_, band_;
  vtkSmartPointer<vtkActor> points_actor_;
  vtkSmartPointer<vtkActor2D> band_actor_;
};

}  // namespace sdog::studio
