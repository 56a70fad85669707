#pragma once
// One DOG mesh in a scene: its surface (coloured by at most one array), its vertices as coloured
// dots (vertex types), its crease polylines and crease points. Positions change in place
// (set_positions), so the actors live as long as the view.
//
// The surface is the trimmed surface (geometry/surface/trimmed_surface.h: each patch clipped at its
// creases, smooth shaded) or, as the debugging view of the DOG itself, the full cells: every quad
// whole, overhanging its patch's creases. The quad grid holds the arrays that colour the surface;
// set_point_array and set_cell_array carry them over to the trimmed surface. With the trimmed
// surface the quad edges (set_edges_visible) are drawn as lines over it, each edge once.
#include <vtkActor.h>
#include <vtkDataSetMapper.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkScalarsToColors.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/mesh/dog_mesh.h"
#include "geometry/mesh/fine_coarse_map.h"
#include "geometry/surface/trimmed_surface.h"

namespace sdog::vis {

/// An unlit actor drawing the poly data in `color`, or in its own RGB point or cell scalars.
vtkSmartPointer<vtkActor> flat_actor(vtkPolyData* data, const std::array<double, 3>& colour);

/// Position of each crease point: the mean of its copies p = t x_v1 + (1 - t) x_v2 in X.
std::vector<Eigen::Vector3d> crease_point_positions(const DogMesh& mesh, const Eigen::MatrixX3d& X);

class MeshView {
 public:
  /// `types`: the vertex types of the mesh's vertices (nullptr without a map: grey dots). The
  /// renderer must outlive the view; the actors are removed by the destructor.
  MeshView(const DogMesh& mesh, const std::vector<VertexType>* types, vtkRenderer* renderer);
  ~MeshView();
  MeshView(const MeshView&) = delete;
  MeshView& operator=(const MeshView&) = delete;

  void set_positions(const Eigen::MatrixX3d& X);
  /// A point array (one value per mesh vertex) or cell array (one per quad) of the surface.
  void set_point_array(const char* name, const std::vector<double>& values);
  void set_cell_array(const char* name, const std::vector<double>& values);
  /// The trimmed surface (default) or the full cells.
  void set_trimmed(bool trimmed);
  /// The paper style's materials (paper_style.h): paper white in front, darker behind, a little
  /// gloss; else the debugging view's plain grey.
  void set_paper(bool paper);
  /// Draws everything moved by (dx, 0, 0) (side-by-side view).
  void set_offset(double dx);
  double offset() const { return offset_; }
  /// Filled surface, or only its edges in `edge_color` (a coarse mesh over the fine one).
  void set_filled(bool filled, const std::array<double, 3>& edge_colour);
  void set_visible(bool visible);

  /// Colours the surface by a point or cell array of the grid through `lut`; nullptr: plain.
  void colour_by(const char* array, bool cell_array, vtkScalarsToColors* lut);
  void set_vertices_visible(bool visible);
  void set_crease_lines_visible(bool visible);
  /// Colours each crease line by its assignment (fold_color; cell arrays `assignment`, 0 to 3 as
  /// in creases.vtp, and `assignment_color`); creases beyond the list: unassigned.
  void set_crease_folds(const std::vector<Fold>& folds);
  void set_crease_points_visible(bool visible);
  void set_edges_visible(bool visible);
  /// Pixel size of the vertex and crease-point dots (crease lines follow).
  void set_dot_size(double pixels);
  /// Pixel width of the crease lines (after set_dot_size, which sets it from the dots).
  void set_crease_line_width(double pixels);

  vtkUnstructuredGrid* grid() const { return grid_; }
  vtkPolyData* crease_lines() const { return crease_lines_; }
  const std::vector<Eigen::Vector3d>& crease_points() const { return crease_positions_; }
  /// The trimmed surface with the carried-over arrays (positions of the last set_positions).
  vtkPolyData* trimmed() const { return trimmed_poly_; }
  /// The actor of the surface on display (trimmed or full cells).
  vtkActor* surface_actor() const { return trimmed_on_ && filled_ ? trimmed_actor_ : surface_; }
  vtkActor* vertex_actor() const { return vertex_actor_; }

 private:
  std::vector<vtkActor*> actors() const;
  void apply_visibility();
  void apply_colours();
  const DogMesh& mesh_;
  vtkRenderer* renderer_;
  double offset_ = 0;
  bool visible_ = true, filled_ = true, trimmed_on_ = true, vertices_ = false,
       crease_lines_on_ = false, crease_points_ = false, edges_ = false;
  vtkSmartPointer<vtkPoints> points_, crease_point_coords_;
  vtkSmartPointer<vtkUnstructuredGrid> grid_;
  vtkSmartPointer<vtkDataSetMapper> surface_mapper_;
  TrimmedSurface trimmed_surface_;
  vtkSmartPointer<vtkPolyData> trimmed_poly_;
  vtkSmartPointer<vtkPolyDataMapper> trimmed_mapper_;
  std::array<double, 3> edge_colour_{};
  const char* colour_array_ = nullptr;  ///< what color_by chose (nullptr: plain)
  bool colour_cells_ = false;
  vtkScalarsToColors* colour_lut_ = nullptr;
  vtkSmartPointer<vtkActor> trimmed_actor_, surface_, vertex_actor_, crease_line_actor_,
      crease_point_actor_;
  vtkSmartPointer<vtkPolyData> vertices_poly_, crease_lines_, crease_points_poly_;
  vtkSmartPointer<vtkPolyData> quad_edges_;  ///< each quad edge once, on the grid's points
  vtkSmartPointer<vtkActor> quad_edge_actor_;
  std::vector<Eigen::Vector3d> crease_positions_;
};

}  // namespace sdog::vis
