#include "ui/vis/vertex_type_picture.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataSetMapper.h>
#include <vtkLegendBoxActor.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

#include "geometry/mesh_arrays.h"
#include "ui/vis/palette.h"
#include "ui/vis/vtk_meshes.h"

namespace sdog::vis {
namespace {

vtkSmartPointer<vtkActor> surface_actor(const DogMesh& mesh, double dx) {
  auto grid = quad_grid(mesh.V, mesh.F, {});
  auto mapper = vtkSmartPointer<vtkDataSetMapper>::New();
  mapper->SetInputData(grid);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetPosition(dx, 0, 0);
  actor->GetProperty()->SetColor(kSurfaceColor[0], kSurfaceColor[1], kSurfaceColor[2]);
  actor->GetProperty()->EdgeVisibilityOn();
  actor->GetProperty()->SetEdgeColor(kEdgeColor[0], kEdgeColor[1], kEdgeColor[2]);
  actor->GetProperty()->SetLighting(false);
  return actor;
}

vtkSmartPointer<vtkActor> point_actor(const std::vector<Eigen::Vector2d>& pts,
                                      const std::vector<Rgb>& colors, double dx, double size,
                                      double z) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
  rgb->SetNumberOfComponents(3);
  rgb->SetName("colors");
  for (size_t k = 0; k < pts.size(); ++k) {
    const vtkIdType id = points->InsertNextPoint(pts[k].x(), pts[k].y(), z);
    verts->InsertNextCell(1, &id);
    const Rgb& c = colors[k];
    rgb->InsertNextTuple3(std::lround(255 * c[0]), std::lround(255 * c[1]),
                          std::lround(255 * c[2]));
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  poly->GetPointData()->SetScalars(rgb);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(poly);
  mapper->SetColorModeToDirectScalars();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetPosition(dx, 0, 0);
  actor->GetProperty()->SetPointSize(static_cast<float>(size));
  actor->GetProperty()->RenderPointsAsSpheresOn();
  actor->GetProperty()->SetLighting(false);
  return actor;
}

vtkSmartPointer<vtkActor> crease_lines_actor(const DogMesh& mesh, double dx, double width) {
  std::vector<Polyline3> lines;
  const auto& st = mesh.stitching;
  for (const auto& c : st.curves) {
    Polyline3 line;
    for (int p : c.points) line.emplace_back(st.points[p].flat.x(), st.points[p].flat.y(), 0.005);
    if (c.closed && !line.empty()) line.push_back(line.front());
    lines.push_back(std::move(line));
  }
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(polylines(lines, {}));
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetPosition(dx, 0, 0);
  actor->GetProperty()->SetColor(kCreaseLineColor[0], kCreaseLineColor[1], kCreaseLineColor[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  actor->GetProperty()->SetLighting(false);
  return actor;
}

void add_mesh(vtkRenderer* ren, const DogMesh& mesh, const std::vector<VertexType>* types,
              double dx, double point_size) {
  ren->AddActor(surface_actor(mesh, dx));
  ren->AddActor(crease_lines_actor(mesh, dx, std::max(1.0, 0.3 * point_size)));
  std::vector<Eigen::Vector2d> pts;
  std::vector<Rgb> colors;
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    pts.push_back(mesh.V.row(v).head<2>().transpose());
    colors.push_back(types ? vertex_type_color((*types)[v]) : Rgb{0.4, 0.4, 0.4});
  }
  ren->AddActor(point_actor(pts, colors, dx, point_size, 0.01));
  std::vector<Eigen::Vector2d> crease_pts;
  for (const auto& p : mesh.stitching.points) crease_pts.push_back(p.flat);
  ren->AddActor(point_actor(crease_pts, std::vector<Rgb>(crease_pts.size(), kCreasePointColor), dx,
                            0.8 * point_size, 0.02));
}

void add_title(vtkRenderer* ren, const std::string& text, double x, int font_size) {
  auto title = vtkSmartPointer<vtkTextActor>::New();
  title->SetInput(text.c_str());
  title->GetTextProperty()->SetFontSize(font_size);
  title->GetTextProperty()->SetColor(kTextColor[0], kTextColor[1], kTextColor[2]);
  title->GetTextProperty()->SetJustificationToCentered();
  title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  title->SetPosition(x, 0.93);
  ren->AddActor2D(title);
}

void add_legend(vtkRenderer* ren, bool coarse, double left) {
  auto square = vtkSmartPointer<vtkPolyData>::New();
  auto pts = vtkSmartPointer<vtkPoints>::New();
  pts->InsertNextPoint(0, 0, 0), pts->InsertNextPoint(1, 0, 0), pts->InsertNextPoint(1, 1, 0),
      pts->InsertNextPoint(0, 1, 0);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType ids[4] = {0, 1, 2, 3};
  polys->InsertNextCell(4, ids);
  square->SetPoints(pts);
  square->SetPolys(polys);
  struct Entry {
    const char* label;
    Rgb color;
  };
  std::vector<Entry> entries;
  if (coarse) {
    entries = {{"link", vertex_type_color(VertexType::Link)},
               {"I: coarse edge midpoint", vertex_type_color(VertexType::I)},
               {"X: coarse quad centre", vertex_type_color(VertexType::X)},
               {"coarse-only", vertex_type_color(VertexType::CoarseOnly)}};
  }
  entries.push_back({"crease point", kCreasePointColor});
  auto legend = vtkSmartPointer<vtkLegendBoxActor>::New();
  legend->SetNumberOfEntries(static_cast<int>(entries.size()));
  for (size_t k = 0; k < entries.size(); ++k) {
    double c[3] = {entries[k].color[0], entries[k].color[1], entries[k].color[2]};
    legend->SetEntry(static_cast<int>(k), square, entries[k].label, c);
  }
  legend->GetEntryTextProperty()->SetColor(kTextColor[0], kTextColor[1], kTextColor[2]);
  legend->BorderOff();
  legend->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  const double h = 0.07 * entries.size();
  legend->GetPositionCoordinate()->SetValue(left, 0.5 - 0.5 * h);
  legend->GetPosition2Coordinate()->SetCoordinateSystemToNormalizedViewport();
  legend->GetPosition2Coordinate()->SetValue(0.99 - left, h);
  ren->AddActor2D(legend);
}

}  // namespace

void render_vertex_types(const DogModel& model, const std::string& path, const ImageSize& size,
                         bool transparent) {
  auto window = offscreen_window(size);
  auto ren = vtkSmartPointer<vtkRenderer>::New();
  ren->SetBackground(1, 1, 1);
  if (transparent) ren->SetBackgroundAlpha(0);
  window->AddRenderer(ren);

  const double width = model.fine.xs.back() - model.fine.xs.front();
  const double height = model.fine.ys.back() - model.fine.ys.front();
  const int panels = model.has_coarse ? 2 : 1;
  const double gap = 0.12 * width;
  const double total_w = panels * width + (panels - 1) * gap;
  // The panels fill the left 80% of the window, the legend the rest.
  const double panel_area = 0.8;
  const double ppu =
      std::min(0.95 * panel_area * size.width / total_w, 0.80 * size.height / height);
  const double point_size = std::clamp(0.45 * ppu, 2.0, 14.0);
  const double x0 = model.fine.xs.front(), y0 = model.fine.ys.front();
  const double focal_x = x0 + 0.5 * total_w + (0.5 - 0.5 * panel_area) * size.width / ppu;
  const double focal_y = y0 + 0.5 * height + 0.03 * size.height / ppu;
  auto to_window_x = [&](double x) { return 0.5 + (x - focal_x) * ppu / size.width; };

  const int font = std::clamp(size.height / 32, 10, 40);
  add_mesh(ren, model.fine, model.has_coarse ? &model.map.fine_type : nullptr, 0, point_size);
  add_title(ren,
            "fine " + model.fine_res.str() + ": " + std::to_string(model.fine.vertex_count()) +
                " vertices, " + std::to_string(model.fine.patch_count()) + " patches",
            to_window_x(x0 + 0.5 * width), font);
  if (model.has_coarse) {
    add_mesh(ren, model.coarse, &model.map.coarse_type, width + gap, point_size);
    add_title(ren,
              "coarse " + model.coarse_res.str() + ": " +
                  std::to_string(model.coarse.vertex_count()) + " vertices",
              to_window_x(x0 + 1.5 * width + gap), font);
  }
  add_legend(ren, model.has_coarse, panel_area + 0.01);

  vtkCamera* cam = ren->GetActiveCamera();
  cam->ParallelProjectionOn();
  cam->SetFocalPoint(focal_x, focal_y, 0);
  cam->SetPosition(focal_x, focal_y, 10 * total_w);
  cam->SetViewUp(0, 1, 0);
  cam->SetParallelScale(0.5 * size.height / ppu);
  ren->ResetCameraClippingRange();
  save_png(window, path, transparent);
}

}  // namespace sdog::vis
