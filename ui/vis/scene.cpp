#include "ui/vis/scene.h"

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkGlyph3D.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "base/errors.h"
#include "ui/vis/colour_maps.h"
#include "ui/vis/legends.h"
#include "ui/vis/mesh_view.h"
#include "ui/vis/palette.h"
#include "ui/vis/vtk_meshes.h"

namespace sdog::vis {
namespace {

constexpr double kSideBySideShift = 1.12;  // sheet widths
constexpr double kPi = 3.14159265358979323846;

vtkSmartPointer<vtkPolyData> poly_data() {
  auto p = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  p->SetPoints(points);
  return p;
}

vtkSmartPointer<vtkTextActor> text_actor(int justification) {
  auto t = vtkSmartPointer<vtkTextActor>::New();
  t->GetTextProperty()->SetColor(kTextColour[0], kTextColour[1], kTextColour[2]);
  t->GetTextProperty()->SetJustification(justification);
  t->GetTextProperty()->SetVerticalJustificationToBottom();
  return t;
}

void merge_bounds(Bounds& into, const double* b) {
  if (b[0] > b[1]) return;  // empty
  for (int k = 0; k < 3; ++k) {
    into[2 * k] = std::min(into[2 * k], b[2 * k]);
    into[2 * k + 1] = std::max(into[2 * k + 1], b[2 * k + 1]);
  }
}

void check_size(size_t got, int expected, const char* what) {
  if (static_cast<int>(got) != expected)
    throw std::logic_error(std::string("scene state: ") + what + " has " + std::to_string(got) +
                           " entries, the model " + std::to_string(expected));
}

}  // namespace

// The actors of the layers that are not part of a mesh view.
struct Scene::Overlays {
  vtkSmartPointer<vtkPolyData> links = poly_data();
  vtkSmartPointer<vtkActor> links_actor = flat_actor(links, kLinkLineColour);

  vtkSmartPointer<vtkPolyData> gaps = poly_data();
  vtkSmartPointer<vtkLookupTable> gap_lut = heat_lut(0, 1);
  vtkSmartPointer<vtkGlyph3D> glyphs = vtkSmartPointer<vtkGlyph3D>::New();
  vtkSmartPointer<vtkActor> gap_actor;

  // Handles: point 2k is handle k, point 2k + 1 its target; line k joins them.
  vtkSmartPointer<vtkPolyData> handle_lines = poly_data();
  vtkSmartPointer<vtkPolyData> handle_points = vtkSmartPointer<vtkPolyData>::New();
  vtkSmartPointer<vtkPolyData> target_points = vtkSmartPointer<vtkPolyData>::New();
  vtkSmartPointer<vtkPolyData> angle_sites = poly_data();
  vtkSmartPointer<vtkActor> residual_actor = flat_actor(handle_lines, kResidualLineColour);
  vtkSmartPointer<vtkActor> handle_actor = flat_actor(handle_points, kHandleColour);
  vtkSmartPointer<vtkActor> target_actor = flat_actor(target_points, kTargetColour);
  vtkSmartPointer<vtkActor> angle_actor = flat_actor(angle_sites, kAngleSiteColour);

  vtkSmartPointer<vtkLookupTable> residual_lut = dog_residual_lut();
  vtkSmartPointer<vtkLookupTable> bending_lut = sequential_lut(0, 1);
  vtkSmartPointer<vtkLookupTable> strain_lut = sequential_lut(0, 1);
  vtkSmartPointer<vtkLookupTable> patch_lut;

  vtkSmartPointer<vtkTextActor> fine_title = text_actor(VTK_TEXT_CENTERED);
  vtkSmartPointer<vtkTextActor> coarse_title = text_actor(VTK_TEXT_CENTERED);
  vtkSmartPointer<vtkTextActor> caption = text_actor(VTK_TEXT_LEFT);

  std::map<Layer, Legend> legends;

  Overlays() {
    auto sphere = vtkSmartPointer<vtkSphereSource>::New();
    sphere->SetThetaResolution(16);
    sphere->SetPhiResolution(12);
    sphere->SetRadius(1);
    glyphs->SetSourceConnection(sphere->GetOutputPort());
    glyphs->SetInputData(gaps);
    glyphs->SetScaleModeToScaleByScalar();
    glyphs->SetColorModeToColorByScalar();
    glyphs->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "radius");
    glyphs->SetInputArrayToProcess(3, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "stitch_gap");
    glyphs->OrientOff();
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(glyphs->GetOutputPort());
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray("stitch_gap");
    mapper->SetLookupTable(gap_lut);
    mapper->UseLookupTableScalarRangeOn();
    mapper->ScalarVisibilityOn();
    gap_actor = vtkSmartPointer<vtkActor>::New();
    gap_actor->SetMapper(mapper);
    handle_points->SetPoints(handle_lines->GetPoints());
    target_points->SetPoints(handle_lines->GetPoints());
    for (vtkActor* a : {handle_actor.Get(), target_actor.Get(), angle_actor.Get()})
      a->GetProperty()->RenderPointsAsSpheresOn();
    residual_actor->GetProperty()->SetLineWidth(3);
    links_actor->GetProperty()->SetLineWidth(1.5);
    fine_title->GetPositionCoordinate()->SetCoordinateSystemToWorld();
    coarse_title->GetPositionCoordinate()->SetCoordinateSystemToWorld();
    caption->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    caption->SetPosition(0.01, 0.95);
  }

  std::vector<vtkActor*> actors() const {
    return {links_actor, gap_actor, residual_actor, handle_actor, target_actor, angle_actor};
  }
  std::vector<vtkTextActor*> texts() const { return {fine_title, coarse_title, caption}; }
};

Scene::Scene(const DogModel& model, vtkRenderer* renderer, const SceneOptions& options)
    : model_(model),
      renderer_(renderer),
      options_(options),
      overlays_(std::make_unique<Overlays>()) {
  fine_ = std::make_unique<MeshView>(model.fine, model.has_coarse ? &model.map.fine_type : nullptr,
                                     renderer);
  if (model.has_coarse)
    coarse_ = std::make_unique<MeshView>(model.coarse, &model.map.coarse_type, renderer);
  Overlays& o = *overlays_;
  for (vtkActor* a : o.actors()) renderer_->AddActor(a);
  for (vtkTextActor* t : o.texts()) renderer_->AddActor2D(t);

  // Link lines: point 2k is fine link vertex k, point 2k + 1 its coarse twin.
  if (model.has_coarse) {
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    vtkIdType next = 0;
    for (int v = 0; v < model.fine.vertex_count(); ++v) {
      if (model.map.fine_to_coarse[v] < 0) continue;
      const vtkIdType ids[2] = {next, next + 1};
      lines->InsertNextCell(2, ids);
      next += 2;
    }
    o.links->GetPoints()->SetNumberOfPoints(next);
    o.links->SetLines(lines);
  }

  const std::string fine_title = "fine " + model.fine_res.str() + ": " +
                                 std::to_string(model.fine.vertex_count()) + " vertices, " +
                                 std::to_string(model.fine.patch_count()) + " patches";
  o.fine_title->SetInput(fine_title.c_str());
  if (model.has_coarse) {
    const std::string coarse_title = "coarse " + model.coarse_res.str() + ": " +
                                     std::to_string(model.coarse.vertex_count()) + " vertices";
    o.coarse_title->SetInput(coarse_title.c_str());
  }

  add_legends();
  for (const auto& [layer, legend] : o.legends) legend.add_to(renderer_);

  // Patches do not change: their cell arrays are set once.
  fine_->set_cell_array("patch", quad_patch(model.fine).values);
  if (coarse_) coarse_->set_cell_array("patch", quad_patch(model.coarse).values);
  for (Layer l : enum_values<Layer>()) on_[l] = false;
  update(rest_scene_state(model));
  apply_view();
}

void Scene::add_legends() {
  Overlays& o = *overlays_;
  o.patch_lut = categorical_lut(model_.fine.patch_count());
  std::vector<LegendEntry> types;
  if (model_.has_coarse)
    types = {{"link", vertex_type_colour(VertexType::kLink)},
             {"I: on a coarse edge", vertex_type_colour(VertexType::kI)},
             {"X: in a coarse quad", vertex_type_colour(VertexType::kX)},
             {"coarse-only", vertex_type_colour(VertexType::kCoarseOnly)}};
  else
    types = {{"vertex (no coarse mesh)", kUntypedVertexColour}};
  types.push_back({"crease point", kCreasePointColour});
  const std::vector<LegendEntry> patches = patch_legend_entries(model_.fine.patch_count());
  o.legends.emplace(Layer::kVertexTypes, Legend::categories("vertex type", types));
  o.legends.emplace(Layer::kLinks,
                    Legend::categories("links", {{"link to coarse twin", kLinkLineColour}}));
  o.legends.emplace(Layer::kPatches,
                    Legend::categories(model_.fine.patch_count() > kPatchColours
                                           ? std::to_string(model_.fine.patch_count()) + " patches"
                                           : std::string("patches"),
                                       patches));
  o.legends.emplace(Layer::kDogResidual,
                    Legend::scalar_bar("DOG residual (log10)", o.residual_lut));
  o.legends.emplace(Layer::kEdgeStrain, Legend::scalar_bar("edge strain", o.strain_lut));
  o.legends.emplace(Layer::kStitchGap, Legend::scalar_bar("stitch gap", o.gap_lut));
  o.legends.emplace(Layer::kBending, Legend::scalar_bar("bending", o.bending_lut));
  o.legends.emplace(Layer::kHandles,
                    Legend::categories("constraints", {{"handle", kHandleColour},
                                                       {"target", kTargetColour},
                                                       {"handle to target", kResidualLineColour},
                                                       {"angle constraint", kAngleSiteColour}}));
  o.legends.emplace(Layer::kCreaseCurves,
                    Legend::categories("creases", crease_legend_entries(model_.fine.stitching)));
}

Scene::~Scene() {
  for (vtkActor* a : overlays_->actors()) renderer_->RemoveActor(a);
  for (vtkTextActor* t : overlays_->texts()) renderer_->RemoveActor2D(t);
  for (const auto& [layer, legend] : overlays_->legends) legend.remove_from(renderer_);
}

void Scene::update(const SceneState& state) {
  check_size(state.fine.rows(), model_.fine.vertex_count(), "fine positions");
  if (state.coarse.rows() > 0)
    check_size(state.coarse.rows(), model_.coarse.vertex_count(), "coarse positions");
  check_size(state.fields.dog_residual.size(), model_.fine.vertex_count(), "dog_residual");
  check_size(state.fields.bending.size(), model_.fine.vertex_count(), "bending");
  check_size(state.fields.edge_strain.size(), model_.fine.quad_count(), "edge_strain");
  check_size(state.fields.stitch_gap.size(), static_cast<int>(model_.fine.stitching.points.size()),
             "stitch_gap");
  for (const auto& h : state.constraints.handles)
    if (h.vertex < 0 || h.vertex >= model_.fine.vertex_count())
      throw std::logic_error("scene state: handle on vertex " + std::to_string(h.vertex) +
                             " out of range");
  for (const auto& a : state.constraints.angle_sites)
    if (a.point < 0 || a.point >= static_cast<int>(model_.fine.stitching.points.size()))
      throw std::logic_error("scene state: angle site at crease point " + std::to_string(a.point) +
                             " out of range");
  if (!state.crease_folds.empty())
    check_size(state.crease_folds.size(), static_cast<int>(model_.fine.stitching.curves.size()),
               "crease_folds");
  state_ = state;
  refresh();
}

double Scene::coarse_offset() const {
  return options_.view == View::kSideBySide
             ? kSideBySideShift * (model_.fine.xs.back() - model_.fine.xs.front())
             : 0;
}

void Scene::refresh() {
  const bool flat = options_.view == View::kFlat;
  const Eigen::MatrixX3d& fine_x = flat ? model_.fine.V : state_.fine;
  refresh_fine(fine_x);
  if (coarse_)
    refresh_coarse(fine_x, flat || state_.coarse.rows() == 0 ? model_.coarse.V : state_.coarse);
  refresh_stitch_gaps();
  refresh_handles(fine_x, flat);
  refresh_crease_folds();
  apply_layers();
}

void Scene::refresh_fine(const Eigen::MatrixX3d& fine_x) {
  Overlays& o = *overlays_;
  fine_->set_positions(fine_x);
  fine_->set_point_array("dog_residual", state_.fields.dog_residual);
  fine_->set_point_array("log10_dog_residual", log10_residuals(state_.fields.dog_residual));
  fine_->set_point_array("bending", state_.fields.bending);
  fine_->set_cell_array("edge_strain", state_.fields.edge_strain);
  const auto bending = robust_range(state_.fields.bending);
  o.bending_lut->SetTableRange(bending[0], bending[1]);
  const auto strain = robust_range(state_.fields.edge_strain);
  o.strain_lut->SetTableRange(strain[0], strain[1]);
}

// The coarse mesh and the links from every fine link vertex to its coarse twin.
void Scene::refresh_coarse(const Eigen::MatrixX3d& fine_x, const Eigen::MatrixX3d& coarse_x) {
  coarse_->set_positions(coarse_x);
  const double dx = coarse_offset();
  vtkPoints* lp = overlays_->links->GetPoints();
  vtkIdType next = 0;
  for (int v = 0; v < model_.fine.vertex_count(); ++v) {
    const int c = model_.map.fine_to_coarse[v];
    if (c < 0) continue;
    lp->SetPoint(next++, fine_x(v, 0), fine_x(v, 1), fine_x(v, 2));
    lp->SetPoint(next++, coarse_x(c, 0) + dx, coarse_x(c, 1), coarse_x(c, 2));
  }
  lp->Modified();
}

// Stitch gaps: a sphere at each crease point, radius 0.15 to 0.6 fine grid spacings with the gap.
void Scene::refresh_stitch_gaps() {
  Overlays& o = *overlays_;
  const auto& creases = fine_->crease_points();
  const auto gap_range = zero_based_range(state_.fields.stitch_gap);
  o.gap_lut->SetTableRange(gap_range[0], gap_range[1]);
  vtkPoints* gp = o.gaps->GetPoints();
  gp->SetNumberOfPoints(static_cast<vtkIdType>(creases.size()));
  std::vector<double> radius(creases.size());
  for (size_t k = 0; k < creases.size(); ++k) {
    gp->SetPoint(static_cast<vtkIdType>(k), creases[k].data());
    radius[k] = 0.15 + 0.45 * state_.fields.stitch_gap[k] / gap_range[1];
  }
  gp->Modified();
  set_double_array(o.gaps->GetPointData(), "stitch_gap", state_.fields.stitch_gap);
  set_double_array(o.gaps->GetPointData(), "radius", radius);
}

// Handles (targets and residual lines only where positions are current: not in the flat view) and
// angle-constraint sites.
void Scene::refresh_crease_folds() {
  std::vector<Fold> folds = state_.crease_folds;
  if (folds.empty())
    for (const auto& c : model_.fine.stitching.curves) folds.push_back(c.fold);
  fine_->set_crease_folds(folds);
  if (coarse_) coarse_->set_crease_folds(folds);
}

void Scene::refresh_handles(const Eigen::MatrixX3d& fine_x, bool flat) {
  Overlays& o = *overlays_;
  vtkPoints* hp = o.handle_lines->GetPoints();
  const auto& handles = state_.constraints.handles;
  hp->SetNumberOfPoints(static_cast<vtkIdType>(2 * handles.size()));
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto handle_verts = vtkSmartPointer<vtkCellArray>::New();
  auto target_verts = vtkSmartPointer<vtkCellArray>::New();
  for (size_t k = 0; k < handles.size(); ++k) {
    const vtkIdType ids[2] = {static_cast<vtkIdType>(2 * k), static_cast<vtkIdType>(2 * k + 1)};
    const Eigen::Vector3d handle = fine_x.row(handles[k].vertex).transpose();
    hp->SetPoint(ids[0], handle.data());
    hp->SetPoint(ids[1], flat ? handle.data() : handles[k].target.data());
    lines->InsertNextCell(2, ids);
    handle_verts->InsertNextCell(1, &ids[0]);
    target_verts->InsertNextCell(1, &ids[1]);
  }
  hp->Modified();
  o.handle_lines->SetLines(lines);
  o.handle_points->SetVerts(handle_verts);
  o.target_points->SetVerts(target_verts);
  const auto& creases = fine_->crease_points();
  vtkPoints* ap = o.angle_sites->GetPoints();
  const auto& sites = state_.constraints.angle_sites;
  ap->SetNumberOfPoints(static_cast<vtkIdType>(sites.size()));
  auto site_verts = vtkSmartPointer<vtkCellArray>::New();
  for (size_t k = 0; k < sites.size(); ++k) {
    const vtkIdType id = static_cast<vtkIdType>(k);
    ap->SetPoint(id, creases[sites[k].point].data());
    site_verts->InsertNextCell(1, &id);
  }
  ap->Modified();
  o.angle_sites->SetVerts(site_verts);
}

void Scene::set_layer(Layer layer, bool on) {
  if (on && is_colour_layer(layer))
    for (auto& [other, other_on] : on_)
      if (other != layer && is_colour_layer(other)) other_on = false;
  on_[layer] = on;
  apply_layers();
}

bool Scene::layer_on(Layer layer) const {
  return on_.at(layer);
}

std::vector<Layer> Scene::layers_on() const {
  std::vector<Layer> out;
  for (Layer l : enum_values<Layer>())
    if (on_.at(l)) out.push_back(l);
  return out;
}

std::optional<Layer> Scene::colour_layer() const {
  for (Layer l : enum_values<Layer>())
    if (is_colour_layer(l) && on_.at(l)) return l;
  return std::nullopt;
}

void Scene::set_options(const SceneOptions& options) {
  options_ = options;
  apply_view();
}

void Scene::set_caption(const std::string& text) {
  overlays_->caption->SetInput(text.c_str());
}

void Scene::apply_view() {
  const bool side = options_.view == View::kSideBySide;
  if (coarse_) {
    coarse_->set_visible(side || options_.coarse);
    coarse_->set_filled(side, side ? kEdgeColour : kCoarseEdgeColour);
    coarse_->set_offset(coarse_offset());
  }
  refresh();  // positions depend on the view (flat: rest positions; links: the offset)
}

void Scene::apply_layers() {
  Overlays& o = *overlays_;
  const std::optional<Layer> colour = colour_layer();
  const bool types = on_[Layer::kVertexTypes], creases = on_[Layer::kCreaseCurves];
  for (MeshView* view : {fine_.get(), coarse_.get()}) {
    if (!view) continue;
    view->set_vertices_visible(types);
    view->set_crease_points_visible(types || creases);
    view->set_crease_lines_visible(creases);
    view->set_edges_visible(on_[Layer::kWireframe]);
    view->set_trimmed(!on_[Layer::kFullCells]);
    view->set_paper(options_.paper);
    if (options_.paper) view->set_crease_points_visible(false);
  }
  switch (colour.value_or(Layer::kWireframe)) {  // wireframe: not a colour layer
    case Layer::kPatches:
      fine_->colour_by("patch", true, o.patch_lut);
      if (coarse_) coarse_->colour_by("patch", true, o.patch_lut);
      break;
    case Layer::kDogResidual:
      fine_->colour_by("log10_dog_residual", false, o.residual_lut);
      break;
    case Layer::kEdgeStrain:
      fine_->colour_by("edge_strain", true, o.strain_lut);
      break;
    case Layer::kBending:
      fine_->colour_by("bending", false, o.bending_lut);
      break;
    default:
      fine_->colour_by(nullptr, false, nullptr);
  }
  if (coarse_ && !(colour && *colour == Layer::kPatches))
    coarse_->colour_by(nullptr, false, nullptr);

  const bool coarse_shown = coarse_ && (options_.view == View::kSideBySide || options_.coarse);
  o.links_actor->SetVisibility(on_[Layer::kLinks] && coarse_shown);
  o.gap_actor->SetVisibility(on_[Layer::kStitchGap]);
  for (vtkActor* a :
       {o.residual_actor.Get(), o.handle_actor.Get(), o.target_actor.Get(), o.angle_actor.Get()})
    a->SetVisibility(on_[Layer::kHandles]);
  o.fine_title->SetVisibility(options_.view == View::kSideBySide && !options_.paper);
  o.coarse_title->SetVisibility(options_.view == View::kSideBySide && coarse_ && !options_.paper);
  for (const auto& [layer, legend] : o.legends) legend.set_visible(on_[layer] && !options_.paper);
  layout_legends();
}

ImageSize Scene::viewport_size() const {
  const int* size = renderer_->GetRenderWindow() ? renderer_->GetSize() : nullptr;
  ImageSize s;  // 1600 x 800
  if (size && size[0] > 0) s.width = size[0];
  if (size && size[1] > 0) s.height = size[1];
  return s;
}

void Scene::layout_legends() {
  Overlays& o = *overlays_;
  std::vector<const Legend*> stack;
  for (Layer l : enum_values<Layer>())
    if (o.legends.count(l)) stack.push_back(&o.legends.at(l));
  const ImageSize size = viewport_size();
  stack_legends(stack, size.width, size.height, options_.font_size);
  for (vtkTextActor* t : o.texts()) t->GetTextProperty()->SetFontSize(options_.font_size);
  // The side-by-side titles: each no wider than the distance between the panels' centres (an
  // estimate: 0.55 em per character), so that they never run into each other.
  if (options_.view == View::kSideBySide && coarse_ && renderer_->GetRenderWindow()) {
    const double a =
        o.fine_title->GetPositionCoordinate()->GetComputedDoubleDisplayValue(renderer_)[0];
    const double b =
        o.coarse_title->GetPositionCoordinate()->GetComputedDoubleDisplayValue(renderer_)[0];
    const double chars = static_cast<double>(
        std::max(std::strlen(o.fine_title->GetInput()), std::strlen(o.coarse_title->GetInput())));
    const int fitting = static_cast<int>(0.9 * std::abs(b - a) / (0.55 * chars));
    const int font = std::max(6, std::min(options_.font_size, fitting));
    o.fine_title->GetTextProperty()->SetFontSize(font);
    o.coarse_title->GetTextProperty()->SetFontSize(font);
  }
}

void Scene::reset_camera() {
  Overlays& o = *overlays_;
  const ImageSize size = viewport_size();
  const double width = size.width, height = size.height;
  Bounds b{1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  merge_bounds(b, fine_->grid()->GetBounds());
  if (coarse_ && coarse_->surface_actor()->GetVisibility()) {
    double cb[6];
    coarse_->grid()->GetBounds(cb);
    cb[0] += coarse_->offset(), cb[1] += coarse_->offset();
    merge_bounds(b, cb);
  }
  if (on_[Layer::kHandles] && o.handle_lines->GetNumberOfPoints() > 0)
    merge_bounds(b, o.handle_lines->GetBounds());

  const bool legends = !options_.paper;
  CameraPose pose;
  if (options_.view == View::kThreeD) {  // framing what is drawn, point by point
    pose = three_d_camera(drawn_points(), width / height, legends);
  } else {
    pose = top_view_camera(b, width / height, legends);
  }
  apply_camera_pose(pose, renderer_->GetActiveCamera());
  renderer_->ResetCameraClippingRange();

  // Dots scale with the zoom of the default camera: pixels per mesh unit at the focal point.
  const double half_height = pose.parallel ? pose.parallel_scale
                                           : (pose.position - pose.focal_point).norm() *
                                                 std::tan(0.5 * pose.view_angle * kPi / 180);
  const double ppu = 0.5 * height / half_height;
  const double dot = std::clamp(0.45 * ppu, 2.0, 14.0);
  for (MeshView* view : {fine_.get(), coarse_.get()}) {
    if (!view) continue;
    view->set_dot_size(dot);
    if (options_.paper) view->set_crease_line_width(std::max(2.0, height / 350));  // print weight
  }
  o.handle_actor->GetProperty()->SetPointSize(static_cast<float>(1.8 * dot));
  o.target_actor->GetProperty()->SetPointSize(static_cast<float>(1.5 * dot));
  o.angle_actor->GetProperty()->SetPointSize(static_cast<float>(1.6 * dot));

  // Titles above the two panels (side-by-side), in world units so they follow the camera.
  const double top = b[3] + 0.06 * (b[3] - b[2]);
  const double fine_centre = 0.5 * (model_.fine.xs.front() + model_.fine.xs.back());
  o.fine_title->SetPosition(fine_centre, top);
  o.coarse_title->SetPosition(fine_centre + coarse_offset(), top);
  layout_legends();
}

std::vector<Eigen::Vector3d> Scene::drawn_points() const {
  std::vector<Eigen::Vector3d> points;
  auto add = [&](vtkDataSet* data, double dx) {
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
      double p[3];
      data->GetPoint(i, p);
      points.emplace_back(p[0] + dx, p[1], p[2]);
    }
  };
  add(on_.at(Layer::kFullCells) ? static_cast<vtkDataSet*>(fine_->grid()) : fine_->trimmed(), 0);
  if (coarse_ && coarse_->surface_actor()->GetVisibility()) add(coarse_->grid(), coarse_->offset());
  if (on_.at(Layer::kHandles)) add(overlays_->handle_lines, 0);
  return points;
}

void Scene::frame_all() {
  if (options_.view !=
      View::kThreeD) {  // the top views show the rest state: their default frames it
    reset_camera();
    return;
  }
  const ImageSize size = viewport_size();
  const double width = size.width, height = size.height;
  vtkCamera* camera = renderer_->GetActiveCamera();
  apply_camera_pose(
      framed_camera(drawn_points(), camera_pose(camera), width / height, !options_.paper), camera);
  renderer_->ResetCameraClippingRange();
}

vtkDataSet* Scene::layer_data(Layer layer) const {
  switch (layer) {
    case Layer::kLinks:
      return overlays_->links;
    case Layer::kStitchGap:
      return overlays_->gaps;
    case Layer::kHandles:
      return overlays_->handle_lines;
    case Layer::kCreaseCurves:
      return fine_->crease_lines();
    default:
      return fine_->grid();
  }
}

vtkPolyData* Scene::trimmed_surface() const {
  return fine_->trimmed();
}

vtkProp* Scene::legend_prop(Layer layer) const {
  const auto it = overlays_->legends.find(layer);
  if (it == overlays_->legends.end()) return nullptr;
  return it->second.bar() ? static_cast<vtkProp*>(it->second.bar()) : it->second.title();
}

std::pair<vtkTextActor*, vtkTextActor*> Scene::panel_titles() const {
  return {overlays_->fine_title, overlays_->coarse_title};
}

const Legend* Scene::legend(Layer layer) const {
  const auto it = overlays_->legends.find(layer);
  return it == overlays_->legends.end() ? nullptr : &it->second;
}

}  // namespace sdog::vis
