#pragma once
// A scene of a DOG model in a vtkRenderer: the fine mesh, optionally the coarse mesh, and the
// overlay layers (layers.h) switched on and off, each with its legend in a column at the right
// edge. The studio holds one per view and calls update() after solver iterations; sdog render
// draws one offscreen (picture.h).
//
// Views:
// - 3d: the current positions, 3D camera; with `coarse` the coarse mesh (its edges, blue) over
//   the fine one in the same units;
// - flat: the rest positions (the crease pattern laid out flat), top camera; with `coarse` the
//   coarse mesh's edges over the fine mesh;
// - side-by-side: the fine mesh (left) and the coarse mesh (right, moved by 1.12 sheet widths),
//   current positions, top camera, a title above each.
// A scene belongs to the thread that renders (VTK is not thread safe): a solver thread hands over
// SceneState values, it never touches the scene.
// Coarse positions are those of a mode that steps a coarse mesh (SceneState::coarse), otherwise
// its rest state. Layers that only exist on the fine mesh (residuals, strain, bending, stitch gap,
// handles) are drawn on the fine mesh only.
#include <vtkDataSet.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/enum_names.h"

#include "geometry/mesh/dog_model.h"
#include "ui/vis/camera.h"
#include "ui/vis/layers.h"
#include "ui/vis/legends.h"
#include "ui/vis/offscreen.h"
#include "ui/vis/scene_state.h"

namespace sdog::vis {

enum class View { kThreeD, kFlat, kSideBySide };
}  // namespace sdog::vis
namespace sdog {
template <>
struct EnumNames<vis::View> {
  static constexpr const char* noun = "view";
  static constexpr EnumName<vis::View> rows[] = {
      {vis::View::kThreeD, "3d"},
      {vis::View::kFlat, "flat"},
      {vis::View::kSideBySide, "side-by-side"},
  };
};
}  // namespace sdog
namespace sdog::vis {

struct SceneOptions {
  View view = View::kThreeD;
  bool coarse = false;  ///< show the coarse mesh (side-by-side always does when the model has one)
  int font_size = 20;   ///< legends and titles (points)
  /// The paper style (paper_style.h): no legends, titles or crease-point dots, a paper-coloured
  /// surface and crease lines coloured by assignment.
  bool paper = false;
};

class Legend;
class MeshView;

class Scene {
 public:
  /// Adds the scene's actors to `renderer`. The model and the renderer must outlive the scene
  /// (its destructor removes the actors). Starts in the model's rest state, every layer off.
  Scene(const DogModel& model, vtkRenderer* renderer, const SceneOptions& options = {});
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  /// New positions, fields and constraints: refreshes the data of the existing actors (the
  /// camera stays). Throws std::logic_error when the sizes do not match the model.
  void update(const SceneState& state);
  const SceneState& state() const { return state_; }

  /// Switches a layer on or off. Turning a colour layer on turns the one that was on off.
  void set_layer(Layer layer, bool on);
  bool layer_on(Layer layer) const;
  /// The layers that are on, in the order of enum_values<Layer>().
  std::vector<Layer> layers_on() const;
  /// The colour layer that is on, if any.
  std::optional<Layer> colour_layer() const;

  void set_options(const SceneOptions& options);
  const SceneOptions& options() const { return options_; }
  /// A line of text at the top left (empty: none).
  void set_caption(const std::string& text);

  /// The view's default camera (camera.h) fitted to what is drawn now, for the renderer's current
  /// aspect ratio; also sizes the dots to the zoom. Call it after the render window has its size.
  void reset_camera();
  /// The 3D view's camera, kept looking the way it looks, moved so that everything drawn now lies
  /// inside the drawing area (View > Frame all); the top views get their default camera.
  void frame_all();
  /// The points of what is drawn in the 3D view: the sheet (trimmed or its full cells), the coarse
  /// mesh when shown, the handles and targets when on.
  std::vector<Eigen::Vector3d> drawn_points() const;
  /// Re-places the legends for the renderer's current size (after a resize).
  void layout_legends();

  /// The data a layer draws on the fine mesh, for inspection and tests: the fine grid (point
  /// arrays vertex_type_color, dog_residual, log10_dog_residual, bending; cell arrays patch,
  /// edge_strain) for vertex-types, patches, dog-residual, edge-strain, bending and wireframe; one
  /// line per link vertex for links; the crease points (arrays stitch_gap, radius) for stitch-gap;
  /// handle, target and residual-line points and cells for handles; the crease polylines (cell
  /// arrays assignment and assignment_color) for crease-curves.
  vtkDataSet* layer_data(Layer layer) const;
  /// The fine mesh's trimmed surface (positions and the colour arrays of the last update).
  vtkPolyData* trimmed_surface() const;
  /// The legend actor of a layer (a vtkScalarBarActor or vtkLegendBoxActor), nullptr for
  /// wireframe.
  vtkProp* legend_prop(Layer layer) const;
  /// The legend of a layer (nullptr: none).
  const Legend* legend(Layer layer) const;
  /// The titles over the fine and the coarse panel of the side-by-side view.
  std::pair<vtkTextActor*, vtkTextActor*> panel_titles() const;

 private:
  struct Overlays;
  /// The legend of every layer (with the patch colours of the model), made once.
  void add_legends();
  /// The renderer's size in pixels; 1600 x 800 while it has no window (or no size yet).
  ImageSize viewport_size() const;
  void apply_layers();
  void apply_view();
  void refresh();
  void refresh_fine(const Eigen::MatrixX3d& fine_x);
  void refresh_coarse(const Eigen::MatrixX3d& fine_x, const Eigen::MatrixX3d& coarse_x);
  void refresh_stitch_gaps();
  void refresh_handles(const Eigen::MatrixX3d& fine_x, bool flat);
  void refresh_crease_folds();
  double coarse_offset() const;
  const DogModel& model_;
  vtkRenderer* renderer_;
  SceneOptions options_;
  SceneState state_;
  std::map<Layer, bool> on_;
  std::unique_ptr<MeshView> fine_, coarse_;
  std::unique_ptr<Overlays> overlays_;
};

}  // namespace sdog::vis
