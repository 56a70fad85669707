#include "ui/vis/mesh_view.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ui/vis/palette.h"
#include "ui/vis/vtk_meshes.h"

namespace sdog::vis {
namespace {

vtkSmartPointer<vtkCellArray> vertex_cells(vtkIdType n) {
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  for (vtkIdType i = 0; i < n; ++i) verts->InsertNextCell(1, &i);
  return verts;
}

// The colours of the vertex types (one colour for all without types), as 8-bit RGB.
vtkSmartPointer<vtkUnsignedCharArray> vertex_type_colours(const DogMesh& mesh,
                                                          const std::vector<VertexType>* types) {
  auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
  rgb->SetName("vertex_type_color");
  rgb->SetNumberOfComponents(3);
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const Rgb c = types ? vertex_type_colour((*types)[v]) : kUntypedVertexColour;
    rgb->InsertNextTuple3(std::lround(255 * c[0]), std::lround(255 * c[1]),
                          std::lround(255 * c[2]));
  }
  return rgb;
}

// Every quad edge once, as a line between two of the mesh's vertices.
vtkSmartPointer<vtkCellArray> quad_edge_lines(const DogMesh& mesh) {
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  for (int q = 0; q < mesh.quad_count(); ++q)
    for (int k = 0; k < 4; ++k) {
      const vtkIdType a = mesh.F(q, k), b = mesh.F(q, (k + 1) % 4);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  lines->AllocateExact(static_cast<vtkIdType>(edges.size()),
                       2 * static_cast<vtkIdType>(edges.size()));
  for (const auto& [a, b] : edges) {
    const vtkIdType ids[2] = {a, b};
    lines->InsertNextCell(2, ids);
  }
  return lines;
}

}  // namespace

vtkSmartPointer<vtkActor> flat_actor(vtkPolyData* data, const Rgb& colour) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  mapper->SetColorModeToDirectScalars();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLighting(false);
  return actor;
}

std::vector<Eigen::Vector3d> crease_point_positions(const DogMesh& mesh,
                                                    const Eigen::MatrixX3d& X) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(mesh.stitching.points.size());
  for (const auto& p : mesh.stitching.points) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& c : p.copies) sum += DogMesh::position(X, c);
    out.push_back(sum / static_cast<double>(p.copies.size()));
  }
  return out;
}

MeshView::MeshView(const DogMesh& mesh, const std::vector<VertexType>* types, vtkRenderer* renderer)
    : mesh_(mesh), renderer_(renderer) {
  grid_ = quad_grid(mesh.V, mesh.F, {});
  points_ = grid_->GetPoints();
  surface_mapper_ = vtkSmartPointer<vtkDataSetMapper>::New();
  surface_mapper_->SetInputData(grid_);
  surface_mapper_->ScalarVisibilityOff();
  surface_mapper_->InterpolateScalarsBeforeMappingOn();
  surface_ = vtkSmartPointer<vtkActor>::New();
  surface_->SetMapper(surface_mapper_);
  surface_->GetProperty()->SetColor(kSurfaceColour[0], kSurfaceColour[1], kSurfaceColour[2]);
  surface_->GetProperty()->SetEdgeColor(kEdgeColour[0], kEdgeColour[1], kEdgeColour[2]);
  surface_->GetProperty()->SetAmbient(0.35);
  surface_->GetProperty()->SetDiffuse(0.65);

  edge_colour_ = kEdgeColour;
  // The trimmed surface: its topology once, its positions and normals with every state.
  trimmed_surface_ = trimmed_surface(mesh, mesh.V);
  trimmed_poly_ = triangle_surface(trimmed_surface_, {});
  trimmed_mapper_ = vtkSmartPointer<vtkPolyDataMapper>::New();
  trimmed_mapper_->SetInputData(trimmed_poly_);
  trimmed_mapper_->ScalarVisibilityOff();
  trimmed_mapper_->InterpolateScalarsBeforeMappingOn();
  // Pushed back a little, so that the quad edges and crease lines drawn on it stay in front.
  trimmed_mapper_->SetRelativeCoincidentTopologyPolygonOffsetParameters(1, 1);
  trimmed_actor_ = vtkSmartPointer<vtkActor>::New();
  trimmed_actor_->SetMapper(trimmed_mapper_);
  trimmed_actor_->GetProperty()->SetColor(kSurfaceColour[0], kSurfaceColour[1], kSurfaceColour[2]);
  trimmed_actor_->GetProperty()->SetAmbient(0.35);
  trimmed_actor_->GetProperty()->SetDiffuse(0.65);

  // Vertex dots share the grid's points, so they follow every position update.
  vertices_poly_ = vtkSmartPointer<vtkPolyData>::New();
  vertices_poly_->SetPoints(points_);
  vertices_poly_->SetVerts(vertex_cells(mesh.vertex_count()));
  vertices_poly_->GetPointData()->SetScalars(vertex_type_colours(mesh, types));
  vertex_actor_ = flat_actor(vertices_poly_, {0.4, 0.4, 0.4});
  vertex_actor_->GetProperty()->RenderPointsAsSpheresOn();

  // The quad edges over the trimmed surface: each edge once, on the grid's points.
  quad_edges_ = vtkSmartPointer<vtkPolyData>::New();
  quad_edges_->SetPoints(points_);
  quad_edges_->SetLines(quad_edge_lines(mesh));
  quad_edge_actor_ = flat_actor(quad_edges_, kEdgeColour);

  // Crease lines and crease points share the crease points' coordinates.
  crease_point_coords_ = vtkSmartPointer<vtkPoints>::New();
  crease_point_coords_->SetDataTypeToDouble();
  crease_point_coords_->SetNumberOfPoints(static_cast<vtkIdType>(mesh.stitching.points.size()));
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& c : mesh.stitching.curves) {
    lines->InsertNextCell(
        static_cast<int>(c.points.size() + (c.closed && !c.points.empty() ? 1 : 0)));
    for (int p : c.points) lines->InsertCellPoint(p);
    if (c.closed && !c.points.empty()) lines->InsertCellPoint(c.points.front());
  }
  crease_lines_ = vtkSmartPointer<vtkPolyData>::New();
  crease_lines_->SetPoints(crease_point_coords_);
  crease_lines_->SetLines(lines);
  crease_line_actor_ = flat_actor(crease_lines_, fold_colour(Fold::kUnassigned));
  std::vector<Fold> folds;
  for (const auto& c : mesh.stitching.curves) folds.push_back(c.fold);
  set_crease_folds(folds);
  crease_points_poly_ = vtkSmartPointer<vtkPolyData>::New();
  crease_points_poly_->SetPoints(crease_point_coords_);
  crease_points_poly_->SetVerts(vertex_cells(crease_point_coords_->GetNumberOfPoints()));
  crease_point_actor_ = flat_actor(crease_points_poly_, kCreasePointColour);
  crease_point_actor_->GetProperty()->RenderPointsAsSpheresOn();

  for (vtkActor* a : actors()) renderer_->AddActor(a);
  set_positions(mesh.V);
  set_dot_size(6);
  apply_visibility();
}

MeshView::~MeshView() {
  for (vtkActor* a : actors()) renderer_->RemoveActor(a);
}

std::vector<vtkActor*> MeshView::actors() const {
  return {trimmed_actor_,     surface_,      quad_edge_actor_,
          crease_line_actor_, vertex_actor_, crease_point_actor_};
}

void MeshView::set_positions(const Eigen::MatrixX3d& X) {
  for (Eigen::Index i = 0; i < X.rows(); ++i) points_->SetPoint(i, X(i, 0), X(i, 1), X(i, 2));
  points_->Modified();
  place_trimmed_surface(trimmed_surface_, X);
  vtkPoints* tp = trimmed_poly_->GetPoints();
  vtkDataArray* normals = trimmed_poly_->GetPointData()->GetNormals();
  for (int r = 0; r < trimmed_surface_.vertex_count(); ++r) {
    tp->SetPoint(r, trimmed_surface_.V(r, 0), trimmed_surface_.V(r, 1), trimmed_surface_.V(r, 2));
    normals->SetTuple3(r, trimmed_surface_.N(r, 0), trimmed_surface_.N(r, 1),
                       trimmed_surface_.N(r, 2));
  }
  tp->Modified();
  normals->Modified();
  crease_positions_ = crease_point_positions(mesh_, X);
  for (size_t k = 0; k < crease_positions_.size(); ++k)
    crease_point_coords_->SetPoint(static_cast<vtkIdType>(k), crease_positions_[k].data());
  crease_point_coords_->Modified();
}

void MeshView::set_offset(double dx) {
  offset_ = dx;
  for (vtkActor* a : actors()) a->SetPosition(dx, 0, 0);
}

void MeshView::set_point_array(const char* name, const std::vector<double>& values) {
  set_double_array(grid_->GetPointData(), name, values);
  set_double_array(trimmed_poly_->GetPointData(), name,
                   trimmed_point_values(trimmed_surface_, values));
}

void MeshView::set_cell_array(const char* name, const std::vector<double>& values) {
  set_double_array(grid_->GetCellData(), name, values);
  set_double_array(trimmed_poly_->GetCellData(), name,
                   trimmed_cell_values(trimmed_surface_, values));
}

void MeshView::set_paper(bool paper) {
  vtkProperty* front = trimmed_actor_->GetProperty();
  const Rgb colour = paper ? kPaperColour : kSurfaceColour;
  front->SetColor(colour[0], colour[1], colour[2]);
  front->SetAmbient(paper ? 0.15 : 0.35);
  front->SetDiffuse(paper ? 0.8 : 0.65);
  front->SetSpecular(paper ? 0.12 : 0.0);
  front->SetSpecularPower(20);
  if (paper) {
    auto back = vtkSmartPointer<vtkProperty>::New();
    back->DeepCopy(front);
    back->SetColor(kPaperBackColour[0], kPaperBackColour[1], kPaperBackColour[2]);
    trimmed_actor_->SetBackfaceProperty(back);
  } else {
    trimmed_actor_->SetBackfaceProperty(nullptr);
  }
}

void MeshView::set_crease_line_width(double pixels) {
  crease_line_actor_->GetProperty()->SetLineWidth(static_cast<float>(pixels));
}

void MeshView::set_trimmed(bool trimmed) {
  trimmed_on_ = trimmed;
  apply_visibility();
}

void MeshView::set_filled(bool filled, const std::array<double, 3>& edge_colour) {
  filled_ = filled;
  edge_colour_ = edge_colour;
  apply_visibility();
}

void MeshView::set_visible(bool visible) {
  visible_ = visible;
  apply_visibility();
}

void MeshView::colour_by(const char* array, bool cell_array, vtkScalarsToColors* lut) {
  colour_array_ = array;
  colour_cells_ = cell_array;
  colour_lut_ = lut;
  apply_colours();
}

void MeshView::apply_colours() {
  const bool coloured = colour_array_ && colour_lut_ && filled_;
  auto configure = [&](vtkMapper* mapper, bool on) {
    if (!on) {
      mapper->ScalarVisibilityOff();
      return;
    }
    mapper->ScalarVisibilityOn();
    if (colour_cells_)
      mapper->SetScalarModeToUseCellFieldData();
    else
      mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray(colour_array_);
    mapper->SetLookupTable(colour_lut_);
    mapper->UseLookupTableScalarRangeOn();
  };
  configure(trimmed_mapper_, coloured);
  configure(surface_mapper_, coloured);
}

void MeshView::set_vertices_visible(bool visible) {
  vertices_ = visible;
  apply_visibility();
}
void MeshView::set_crease_lines_visible(bool visible) {
  crease_lines_on_ = visible;
  apply_visibility();
}
void MeshView::set_crease_folds(const std::vector<Fold>& folds) {
  auto code = vtkSmartPointer<vtkIntArray>::New();
  code->SetName("assignment");
  auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
  rgb->SetName("assignment_color");
  rgb->SetNumberOfComponents(3);
  for (size_t k = 0; k < mesh_.stitching.curves.size(); ++k) {
    const Fold fold = k < folds.size() ? folds[k] : Fold::kUnassigned;
    code->InsertNextValue(static_cast<int>(fold));
    const Rgb c =
        mesh_.stitching.curves[k].kind == CurveKind::kSlit ? kSlitColour : fold_colour(fold);
    rgb->InsertNextTuple3(std::lround(255 * c[0]), std::lround(255 * c[1]),
                          std::lround(255 * c[2]));
  }
  crease_lines_->GetCellData()->AddArray(code);
  crease_lines_->GetCellData()->SetScalars(rgb);
  crease_lines_->Modified();
}

void MeshView::set_crease_points_visible(bool visible) {
  crease_points_ = visible;
  apply_visibility();
}
void MeshView::set_edges_visible(bool visible) {
  edges_ = visible;
  apply_visibility();
}

void MeshView::set_dot_size(double pixels) {
  vertex_actor_->GetProperty()->SetPointSize(static_cast<float>(pixels));
  crease_point_actor_->GetProperty()->SetPointSize(static_cast<float>(0.8 * pixels));
  crease_line_actor_->GetProperty()->SetLineWidth(static_cast<float>(std::max(1.5, 0.35 * pixels)));
}

void MeshView::apply_visibility() {
  const bool trimmed = trimmed_on_ && filled_;
  trimmed_actor_->SetVisibility(visible_ && trimmed);
  vtkProperty* p = surface_->GetProperty();
  quad_edge_actor_->SetVisibility(visible_ && trimmed && edges_);
  if (trimmed) {  // the quad edges are their own lines over the trimmed surface
    surface_->SetVisibility(false);
  } else if (filled_) {
    surface_->SetVisibility(visible_);
    p->SetRepresentationToSurface();
    p->SetColor(kSurfaceColour[0], kSurfaceColour[1], kSurfaceColour[2]);
    p->SetEdgeColor(edge_colour_[0], edge_colour_[1], edge_colour_[2]);
    p->SetLighting(true);
    p->SetEdgeVisibility(edges_);
  } else {
    surface_->SetVisibility(visible_);
    p->SetRepresentationToWireframe();
    p->SetColor(edge_colour_[0], edge_colour_[1], edge_colour_[2]);
    p->SetLineWidth(2);
    p->SetLighting(false);
    p->SetEdgeVisibility(false);
  }
  vertex_actor_->SetVisibility(visible_ && vertices_);
  crease_line_actor_->SetVisibility(visible_ && crease_lines_on_);
  crease_point_actor_->SetVisibility(visible_ && crease_points_);
  apply_colours();
}

}  // namespace sdog::vis
