// The data behind the scene's layers (no picture is rendered here): one line per link vertex, the
// log-scaled residuals, the stitch gaps, the handles, crease lines coloured by assignment, one
// colour layer at a time, legends that follow their layers, updates that keep the actors.
#include <gtest/gtest.h>
#include <vtkActor2DCollection.h>
#include <vtkActorCollection.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProp.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "base/errors.h"
#include "geometry/surface/trimmed_surface.h"
#include "solver/problem/diagnostics.h"
#include "tests/ui/vis/scene_fixture.h"
#include "ui/vis/camera.h"
#include "ui/vis/layers.h"
#include "ui/vis/mesh_view.h"
#include "ui/vis/scene.h"

namespace sdog {
namespace {

using test::arcs_model;
using test::arcs_standard_state;
using test::arcs_twolevel_state;

struct SceneTest : ::testing::Test {
  vtkSmartPointer<vtkRenderer> renderer = vtkSmartPointer<vtkRenderer>::New();
};

TEST_F(SceneTest, LinksLayerHasOneLinePerLinkVertexFromFineToCoarseTwin) {
  const DogModel& m = arcs_model();
  vis::Scene scene(m, renderer, {vis::View::kThreeD, true});
  scene.update(arcs_twolevel_state());
  auto* links = vtkPolyData::SafeDownCast(scene.layer_data(vis::Layer::kLinks));
  ASSERT_NE(links, nullptr);
  ASSERT_EQ(links->GetNumberOfLines(), m.map.link_count);
  const auto& s = arcs_twolevel_state();
  ASSERT_EQ(s.coarse.rows(), m.coarse.vertex_count());
  int k = 0;
  double moved = 0;
  for (int v = 0; v < m.fine.vertex_count(); ++v) {
    const int c = m.map.fine_to_coarse[v];
    if (c < 0) continue;
    double a[3], b[3];
    links->GetPoint(2 * k, a);
    links->GetPoint(2 * k + 1, b);
    for (int d = 0; d < 3; ++d) {
      EXPECT_DOUBLE_EQ(a[d], s.fine(v, d));
      EXPECT_DOUBLE_EQ(b[d], s.coarse(c, d));
    }
    moved = std::max(
        moved, (Eigen::Vector3d(a[0], a[1], a[2]) - Eigen::Vector3d(b[0], b[1], b[2])).norm());
    ++k;
  }
  EXPECT_GT(moved, 1e-3) << "the twolevel run should leave fine and coarse twins apart";
}

TEST_F(SceneTest, SideBySideLinksEndOnTheShiftedCoarseMesh) {
  const DogModel& m = arcs_model();
  vis::Scene scene(m, renderer, {vis::View::kSideBySide, false});
  auto* links = vtkPolyData::SafeDownCast(scene.layer_data(vis::Layer::kLinks));
  const double shift = 1.12 * (m.fine.xs.back() - m.fine.xs.front());
  double a[3], b[3];
  links->GetPoint(0, a);
  links->GetPoint(1, b);
  EXPECT_NEAR(b[0] - a[0], shift, 1e-9);  // at rest a link vertex and its twin coincide
  EXPECT_NEAR(b[1], a[1], 1e-12);
}

TEST_F(SceneTest, LogResidualArrayIsLog10OfTheResiduals) {
  const DogModel& m = arcs_model();
  vis::Scene scene(m, renderer);
  const vis::SceneState& s = arcs_standard_state();
  scene.update(s);
  vtkDataArray* log_r =
      scene.layer_data(vis::Layer::kDogResidual)->GetPointData()->GetArray("log10_dog_residual");
  ASSERT_NE(log_r, nullptr);
  ASSERT_EQ(log_r->GetNumberOfTuples(), m.fine.vertex_count());
  int above_floor = 0;
  for (int v = 0; v < m.fine.vertex_count(); ++v) {
    const double r = s.fields.dog_residual[v];
    if (r >= vis::kResidualFloor) {
      EXPECT_NEAR(log_r->GetTuple1(v), std::log10(r), 1e-12) << v;
      ++above_floor;
    } else {
      EXPECT_EQ(log_r->GetTuple1(v), -10) << v;
    }
  }
  EXPECT_GT(above_floor, m.fine.vertex_count() / 4) << "a run mid-way leaves residuals above 1e-10";
  EXPECT_EQ(vis::log10_residuals({1e-3, 0, 1e-12, 2.0}),
            (std::vector<double>{-3, -10, -10, std::log10(2.0)}));
}

TEST_F(SceneTest, StitchGapPerCreasePointIsTheDistanceBetweenCopies) {
  const DogModel& m = arcs_model();
  const vis::SceneState& s = arcs_standard_state();
  ASSERT_EQ(s.fields.stitch_gap.size(), m.fine.stitching.points.size());
  // The largest per-point gap is the run's stitch_gap_max.
  DogProblem problem(m.fine, m.fine_topology);
  const Dofs x = to_dofs(s.fine);
  const double gap_max = *std::max_element(s.fields.stitch_gap.begin(), s.fields.stitch_gap.end());
  EXPECT_NEAR(gap_max, diagnose(problem, x).stitch_gap_max, 1e-12);
  EXPECT_GT(gap_max, 1e-4);
  // Point by point, against the copies' positions.
  for (size_t k = 0; k < m.fine.stitching.points.size(); ++k) {
    const auto& copies = m.fine.stitching.points[k].copies;
    double worst = 0;
    for (size_t i = 0; i + 1 < copies.size(); ++i)
      worst = std::max(
          worst,
          (DogMesh::position(s.fine, copies[i]) - DogMesh::position(s.fine, copies[i + 1])).norm());
    EXPECT_NEAR(s.fields.stitch_gap[k], worst, 1e-12) << k;
  }
  vis::Scene scene(m, renderer);
  scene.update(s);
  vtkDataSet* glyphs = scene.layer_data(vis::Layer::kStitchGap);
  ASSERT_EQ(glyphs->GetNumberOfPoints(), static_cast<vtkIdType>(m.fine.stitching.points.size()));
  vtkDataArray* radius = glyphs->GetPointData()->GetArray("radius");
  for (size_t k = 0; k < s.fields.stitch_gap.size(); ++k)
    EXPECT_NEAR(radius->GetTuple1(k), 0.15 + 0.45 * s.fields.stitch_gap[k] / gap_max, 1e-12);
}

TEST_F(SceneTest, HandlesJoinEachHandleToItsTarget) {
  const DogModel& m = arcs_model();
  const vis::SceneState& s = arcs_standard_state();
  ASSERT_EQ(s.constraints.handles.size(), 2u);  // the corners scenario: a held, c dragged
  EXPECT_GT(s.constraints.angle_sites.size(), 0u);
  vis::Scene scene(m, renderer);
  scene.update(s);
  auto* lines = vtkPolyData::SafeDownCast(scene.layer_data(vis::Layer::kHandles));
  ASSERT_EQ(lines->GetNumberOfLines(), 2);
  for (int k = 0; k < 2; ++k) {
    double h[3], t[3];
    lines->GetPoint(2 * k, h);
    lines->GetPoint(2 * k + 1, t);
    for (int d = 0; d < 3; ++d) {
      EXPECT_DOUBLE_EQ(h[d], s.fine(s.constraints.handles[k].vertex, d));
      EXPECT_DOUBLE_EQ(t[d], s.constraints.handles[k].target[d]);
    }
  }
}

TEST_F(SceneTest, CreaseCurvesAreColouredByAssignment) {
  const DogModel& m = arcs_model();
  const auto& curves = m.fine.stitching.curves;
  ASSERT_GE(curves.size(), 2u);
  vis::Scene scene(m, renderer);
  auto* lines = vtkPolyData::SafeDownCast(scene.layer_data(vis::Layer::kCreaseCurves));
  ASSERT_NE(lines, nullptr);
  vtkDataArray* code = lines->GetCellData()->GetArray("assignment");
  ASSERT_NE(code, nullptr);
  ASSERT_EQ(code->GetNumberOfTuples(), static_cast<vtkIdType>(curves.size()));
  for (size_t k = 0; k < curves.size(); ++k)  // without a state's own: the model's
    EXPECT_EQ(static_cast<int>(code->GetTuple1(static_cast<vtkIdType>(k))),
              static_cast<int>(curves[k].fold));
  // A state's assignments win: a red mountain, blue valleys.
  vis::SceneState s = arcs_standard_state();
  s.crease_folds.assign(curves.size(), Fold::kValley);
  s.crease_folds[0] = Fold::kMountain;
  scene.update(s);
  code = lines->GetCellData()->GetArray("assignment");
  EXPECT_EQ(code->GetTuple1(0), 1.0);
  EXPECT_EQ(code->GetTuple1(1), 2.0);
  vtkDataArray* rgb = lines->GetCellData()->GetScalars();
  ASSERT_NE(rgb, nullptr);
  EXPECT_GT(rgb->GetComponent(0, 0), 200);
  EXPECT_LT(rgb->GetComponent(0, 2), 50);
  EXPECT_GT(rgb->GetComponent(1, 2), 200);
  s.crease_folds.pop_back();
  EXPECT_THROW(scene.update(s), std::logic_error);
}

TEST_F(SceneTest, TurningOnAColourLayerTurnsTheOtherOff) {
  vis::Scene scene(arcs_model(), renderer);
  scene.set_layer(vis::Layer::kDogResidual, true);
  scene.set_layer(vis::Layer::kHandles, true);
  scene.set_layer(vis::Layer::kStitchGap, true);
  EXPECT_EQ(scene.colour_layer(), vis::Layer::kDogResidual);
  scene.set_layer(vis::Layer::kBending, true);
  EXPECT_FALSE(scene.layer_on(vis::Layer::kDogResidual));
  EXPECT_TRUE(scene.layer_on(vis::Layer::kBending));
  EXPECT_TRUE(scene.layer_on(vis::Layer::kHandles));  // not colour layers: untouched
  EXPECT_TRUE(scene.layer_on(vis::Layer::kStitchGap));
  EXPECT_EQ(scene.colour_layer(), vis::Layer::kBending);
  EXPECT_FALSE(scene.legend_prop(vis::Layer::kDogResidual)->GetVisibility());
  EXPECT_TRUE(scene.legend_prop(vis::Layer::kBending)->GetVisibility());
  scene.set_layer(vis::Layer::kBending, false);
  EXPECT_FALSE(scene.colour_layer().has_value());
  EXPECT_EQ(scene.layers_on(),
            (std::vector<vis::Layer>{vis::Layer::kStitchGap, vis::Layer::kHandles}));
}

TEST_F(SceneTest, EveryLayerButWireframeAndFullCellsHasALegendShownWithIt) {
  vis::Scene scene(arcs_model(), renderer);
  for (vis::Layer l : enum_values<vis::Layer>()) {
    vtkProp* legend = scene.legend_prop(l);
    if (l == vis::Layer::kWireframe || l == vis::Layer::kFullCells) {
      EXPECT_EQ(legend, nullptr);
      continue;
    }
    ASSERT_NE(legend, nullptr) << enum_name(l);
    EXPECT_FALSE(legend->GetVisibility()) << enum_name(l);
    scene.set_layer(l, true);
    EXPECT_TRUE(legend->GetVisibility()) << enum_name(l);
    scene.set_layer(l, false);
    EXPECT_FALSE(legend->GetVisibility()) << enum_name(l);
  }
}

TEST_F(SceneTest, TheTrimmedSurfaceCarriesTheColourArraysAndFullCellsSwapsIt) {
  const DogModel& m = arcs_model();
  vis::Scene scene(m, renderer, {vis::View::kThreeD});
  scene.update(arcs_standard_state());
  vtkPolyData* trimmed = scene.trimmed_surface();
  ASSERT_NE(trimmed, nullptr);
  // Cut cells add triangles beyond two per quad's share; every triangle lies in a patch.
  EXPECT_GT(trimmed->GetNumberOfCells(), m.fine.quad_count());
  for (const char* name : {"dog_residual", "log10_dog_residual", "bending"}) {
    vtkDataArray* a = trimmed->GetPointData()->GetArray(name);
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(a->GetNumberOfTuples(), trimmed->GetNumberOfPoints()) << name;
  }
  for (const char* name : {"patch", "edge_strain"}) {
    vtkDataArray* a = trimmed->GetCellData()->GetArray(name);
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(a->GetNumberOfTuples(), trimmed->GetNumberOfCells()) << name;
  }
  EXPECT_NE(trimmed->GetPointData()->GetNormals(), nullptr);
  // Its points follow the state (the geometry's trimmed surface of the state's positions).
  double bounds[6];
  trimmed->GetBounds(bounds);
  const TrimmedSurface expected = trimmed_surface(m.fine, arcs_standard_state().fine);
  EXPECT_NEAR(bounds[5], expected.V.col(2).maxCoeff(), 1e-9);
  EXPECT_GT(bounds[5], 1);  // lifted

  // Which actors draw the fine surface: the trimmed one by default, the quads with full-cells.
  auto visible_surfaces = [&]() {
    int n = 0;
    vtkActorCollection* actors = renderer->GetActors();
    actors->InitTraversal();
    while (vtkActor* a = actors->GetNextActor())
      if (a->GetVisibility() && a->GetMapper() &&
          (a->GetMapper()->GetInput() == trimmed ||
           a->GetMapper()->GetInput() == scene.layer_data(vis::Layer::kWireframe)))
        n += a->GetMapper()->GetInput() == trimmed ? 1 : 10;
    return n;
  };
  EXPECT_EQ(visible_surfaces(), 1);  // the trimmed surface alone
  scene.set_layer(vis::Layer::kFullCells, true);
  EXPECT_EQ(visible_surfaces(), 10);  // the quads alone
  scene.set_layer(vis::Layer::kFullCells, false);
  auto visible_lines = [&]() {  // visible actors drawing line cells: each quad edge once
    vtkIdType n = 0;
    vtkActorCollection* actors = renderer->GetActors();
    actors->InitTraversal();
    while (vtkActor* a = actors->GetNextActor())
      if (a->GetVisibility() && a->GetMapper())
        if (auto* poly = vtkPolyData::SafeDownCast(a->GetMapper()->GetInput()))
          n += poly->GetNumberOfLines();
    return n;
  };
  const vtkIdType lines_before = visible_lines();
  scene.set_layer(vis::Layer::kWireframe, true);
  EXPECT_EQ(visible_surfaces(),
            1);  // still the trimmed surface alone, with the quad edges as lines over it
  // The fine quads' edges, each once.
  std::set<std::pair<int, int>> edges;
  for (int q = 0; q < m.fine.quad_count(); ++q)
    for (int k = 0; k < 4; ++k) {
      const int a = m.fine.F(q, k), b = m.fine.F(q, (k + 1) % 4);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  EXPECT_EQ(visible_lines() - lines_before, static_cast<vtkIdType>(edges.size()));
}

TEST_F(SceneTest, UpdateKeepsTheActorsAndMovesThePoints) {
  const DogModel& m = arcs_model();
  vis::Scene scene(m, renderer, {vis::View::kThreeD, true});
  for (vis::Layer l :
       {vis::Layer::kDogResidual, vis::Layer::kHandles, vis::Layer::kStitchGap, vis::Layer::kLinks})
    scene.set_layer(l, true);
  const int actors = renderer->GetActors()->GetNumberOfItems();
  const int props2d = renderer->GetActors2D()->GetNumberOfItems();
  vtkDataSet* grid = scene.layer_data(vis::Layer::kWireframe);
  for (int i = 0; i < 3; ++i) {
    scene.update(i % 2 ? vis::rest_scene_state(m) : arcs_standard_state());
    EXPECT_EQ(renderer->GetActors()->GetNumberOfItems(), actors);
    EXPECT_EQ(renderer->GetActors2D()->GetNumberOfItems(), props2d);
    EXPECT_EQ(scene.layer_data(vis::Layer::kWireframe), grid);
  }
  double p[3];
  grid->GetPoint(m.fine.vertex_count() - 1, p);
  EXPECT_DOUBLE_EQ(p[2], arcs_standard_state().fine(m.fine.vertex_count() - 1, 2));
  // The flat view draws the rest positions whatever the state.
  scene.set_options({vis::View::kFlat, false});
  grid->GetPoint(m.fine.vertex_count() - 1, p);
  EXPECT_DOUBLE_EQ(p[2], 0);
}

TEST_F(SceneTest, SceneRemovesItsActorsWhenDestroyed) {
  {
    vis::Scene scene(arcs_model(), renderer);
    EXPECT_GT(renderer->GetActors()->GetNumberOfItems(), 0);
  }
  EXPECT_EQ(renderer->GetActors()->GetNumberOfItems(), 0);
  EXPECT_EQ(renderer->GetActors2D()->GetNumberOfItems(), 0);
}

TEST_F(SceneTest, StateOfTheWrongSizeIsRejected) {
  vis::Scene scene(arcs_model(), renderer);
  vis::SceneState s = vis::rest_scene_state(arcs_model());
  s.fields.bending.pop_back();
  EXPECT_THROW(scene.update(s), std::logic_error);
  s = vis::rest_scene_state(arcs_model());
  s.constraints.handles.push_back({arcs_model().fine.vertex_count(), Eigen::Vector3d::Zero()});
  EXPECT_THROW(scene.update(s), std::logic_error);
}

}  // namespace
}  // namespace sdog
