#include "ui/studio/selection_marks.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>

#include "ui/vis/palette.h"

namespace sdog::studio {
namespace {

// RGB of the selection (not the handles' orange).
constexpr double kRed = vis::kSelectionColour[0], kGreen = vis::kSelectionColour[1],
                 kBlue = vis::kSelectionColour[2];

}  // namespace

SelectionMarks::SelectionMarks(vtkRenderer* renderer)
    : renderer_(renderer),
      points_(vtkSmartPointer<vtkPolyData>::New()),
      band_(vtkSmartPointer<vtkPolyData>::New()),
      points_actor_(vtkSmartPointer<vtkActor>::New()),
      band_actor_(vtkSmartPointer<vtkActor2D>::New()) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(points_);
  points_actor_->SetMapper(mapper);
  points_actor_->GetProperty()->SetColor(kRed, kGreen, kBlue);
  points_actor_->GetProperty()->SetPointSize(8);
  points_actor_->GetProperty()->RenderPointsAsSpheresOn();
  points_actor_->VisibilityOff();
  renderer_->AddActor(points_actor_);

  auto band_points = vtkSmartPointer<vtkPoints>::New();
  band_points->SetNumberOfPoints(4);
  band_->SetPoints(band_points);
  auto loop = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType ids[5] = {0, 1, 2, 3, 0};
  loop->InsertNextCell(5, ids);
  band_->SetLines(loop);
  auto band_mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  band_mapper->SetInputData(band_);
  band_actor_->SetMapper(band_mapper);
  band_actor_->GetProperty()->SetColor(kRed, kGreen, kBlue);
  band_actor_->GetProperty()->SetLineWidth(2);
  band_actor_->VisibilityOff();
  renderer_->AddActor2D(band_actor_);
}

SelectionMarks::~SelectionMarks() {
  renderer_->RemoveActor(points_actor_);
  renderer_->RemoveActor2D(band_actor_);
}

void SelectionMarks::show_points(const Eigen::MatrixX3d& positions,
                                 const std::vector<int>& selected) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  for (int v : selected) {
    if (v < 0 || v >= positions.rows()) continue;
    const vtkIdType id = points->InsertNextPoint(positions(v, 0), positions(v, 1), positions(v, 2));
    vertices->InsertNextCell(1, &id);
  }
  points_->SetPoints(points);
  points_->SetVerts(vertices);
  points_->Modified();
  points_actor_->SetVisibility(points->GetNumberOfPoints() > 0);
}

void SelectionMarks::show_band(double x0, double y0, double x1, double y1) {
  vtkPoints* p = band_->GetPoints();
  p->SetPoint(0, x0, y0, 0);
  p->SetPoint(1, x1, y0, 0);
  p->SetPoint(2, x1, y1, 0);
  p->SetPoint(3, x0, y1, 0);
  p->Modified();
  band_actor_->VisibilityOn();
}

void SelectionMarks::hide_band() {
  band_actor_->VisibilityOff();
}

bool SelectionMarks::band_visible() const {
  return band_actor_->GetVisibility() != 0;
}

}  // namespace sdog::studio
