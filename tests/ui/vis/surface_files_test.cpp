// The trimmed surface as OBJ and PLY files read back with VTK's readers (counts, area, sheet units,
// normals, colours), the --export format names and file extensions, and the PLY colours against
// the renderer's colours of the same layer.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkLookupTable.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <array>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "base/errors.h"
#include "geometry/surface/trimmed_surface.h"
#include "tests/ui/vis/scene_fixture.h"
#include "tests/vtk_read_back.h"
#include "ui/vis/frame_writer.h"
#include "ui/vis/palette.h"
#include "ui/vis/scene.h"
#include "ui/vis/surface_colours.h"
#include "ui/vis/surface_files.h"

namespace sdog {
namespace {

using test::arcs_model;
using test::arcs_standard_state;

// four_corner_arcs.svg is a 400 x 400 sheet (viewBox 0 0 400 400, y negated: y from -400 to 0);
// at 21x21 grid lines a grid column is 400 / 20 sheet units wide.
constexpr double kArcsSheet = 400, kArcsScale = 20.0 / 400;
// A mesh coordinate along `axis` of four_corner_arcs in sheet units (its drawing's y runs down).
double in_sheet_units(double mesh, int axis) {
  return mesh / kArcsScale + (axis == 1 ? -kArcsSheet : 0);
}

using test::read_poly;
using test::triangle_area;

vis::Rgb8 bytes(const vis::Rgb& c) {
  return {static_cast<unsigned char>(std::lround(255 * c[0])),
          static_cast<unsigned char>(std::lround(255 * c[1])),
          static_cast<unsigned char>(std::lround(255 * c[2]))};
}

TEST(SurfaceFiles, FormatNamesAndExtensions) {
  using vis::SurfaceFormat;
  EXPECT_EQ(vis::parse_surface_formats("obj,ply"),
            (std::vector<SurfaceFormat>{SurfaceFormat::kObj, SurfaceFormat::kPly}));
  EXPECT_EQ(vis::parse_surface_formats("ply"), (std::vector<SurfaceFormat>{SurfaceFormat::kPly}));
  for (const char* bad : {"stl", "obj,", "OBJ", "obj,obj", "", "obj;ply"})
    EXPECT_THROW(vis::parse_surface_formats(bad), UsageError) << bad;
  try {
    vis::parse_surface_formats("obj,stl", "--export: ");
    ADD_FAILURE() << "stl accepted";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "--export: unknown format 'stl' (known: obj, ply, fold)");
  }
  EXPECT_EQ(vis::format_of_path("out/a.OBJ"), SurfaceFormat::kObj);
  EXPECT_EQ(vis::format_of_path("a.b.ply"), SurfaceFormat::kPly);
  EXPECT_EQ(vis::format_of_path("folded.fold"), SurfaceFormat::kFold);
  EXPECT_EQ(vis::format_of_path("out.ply/surface"), std::nullopt);
  EXPECT_EQ(vis::format_of_path("surface.stl"), std::nullopt);
  EXPECT_EQ(vis::with_surface_extension("dir/shape", SurfaceFormat::kPly), "dir/shape.ply");
  EXPECT_EQ(vis::with_surface_extension("dir.v2/shape", SurfaceFormat::kObj), "dir.v2/shape.obj");
  EXPECT_EQ(vis::with_surface_extension("shape.Ply", SurfaceFormat::kObj), "shape.Ply");
}

TEST(SurfaceFiles, SheetUnitsSpanThePatternsSheet) {
  const DogModel& m = arcs_model();
  const Eigen::MatrixX3d sheet = vis::to_sheet_units(m.fine, m.fine.V);
  EXPECT_NEAR(sheet.col(0).minCoeff(), 0, 1e-9);
  EXPECT_NEAR(sheet.col(0).maxCoeff(), kArcsSheet, 1e-9);
  EXPECT_NEAR(sheet.col(1).minCoeff(), -kArcsSheet, 1e-9);
  EXPECT_NEAR(sheet.col(1).maxCoeff(), 0, 1e-9);
  // z scales as x and y do: a point 2 mesh units up is 2 grid columns up.
  Eigen::MatrixX3d up = m.fine.V;
  up.col(2).setConstant(2);
  EXPECT_NEAR(vis::to_sheet_units(m.fine, up)(0, 2), 2 / kArcsScale, 1e-9);
}

struct SurfaceFileTest : ::testing::Test {
  const DogModel& m = arcs_model();
  const TrimmedSurface surface = trimmed_surface(m.fine, arcs_standard_state().fine);
  const MeshArrays arrays = vis::frame_arrays(m, arcs_standard_state().fields);
  const std::string dir = test::temp_dir("surface_files");
};

TEST_F(SurfaceFileTest, ObjReadsBackWithNormalsInSheetUnits) {
  const std::string path = dir + "/surface.obj";
  vis::write_surface_file(vis::SurfaceFormat::kObj, surface, m.fine, vis::Layer::kPatches, arrays,
                          path);
  // VTK's OBJ reader keeps float coordinates: the comparisons allow for them.
  const auto obj = read_poly<vtkOBJReader>(path);
  ASSERT_EQ(obj->GetNumberOfPolys(), surface.triangle_count());
  const double area = surface_area(surface) / (kArcsScale * kArcsScale);
  EXPECT_NEAR(triangle_area(obj), area, 1e-6 * area);
  vtkDataArray* normals = obj->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i) {
    const double* n = normals->GetTuple3(i);
    ASSERT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1, 1e-6);
  }
  // The file itself has every vertex in full precision, in the surface's order.
  std::ifstream text(path);
  std::string line;
  int v = 0;
  while (std::getline(text, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream in(line.substr(2));
    double p[3];
    in >> p[0] >> p[1] >> p[2];
    ASSERT_LT(v, surface.vertex_count());
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(p[k], in_sheet_units(surface.V(v, k), k), 1e-12 * kArcsSheet)
          << "vertex " << v << " axis " << k;
    ++v;
  }
  EXPECT_EQ(v, surface.vertex_count());
  // The bounds: the surface's, scaled up to sheet units and shifted to the sheet's origin.
  double b[6];
  obj->GetBounds(b);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(b[2 * k], in_sheet_units(surface.V.col(k).minCoeff(), k), 1e-6 * kArcsSheet)
        << "axis " << k;
    EXPECT_NEAR(b[2 * k + 1], in_sheet_units(surface.V.col(k).maxCoeff(), k), 1e-6 * kArcsSheet)
        << "axis " << k;
  }
}

TEST_F(SurfaceFileTest, PlyReadsBackWithNormalsAndPatchColours) {
  const std::string path = dir + "/surface.ply";
  vis::write_surface_file(vis::SurfaceFormat::kPly, surface, m.fine, vis::Layer::kPatches, arrays,
                          path);
  const auto ply = read_poly<vtkPLYReader>(path);
  ASSERT_EQ(ply->GetNumberOfPoints(), surface.vertex_count());
  ASSERT_EQ(ply->GetNumberOfPolys(), surface.triangle_count());
  const double area = surface_area(surface) / (kArcsScale * kArcsScale);
  EXPECT_NEAR(triangle_area(ply), area, 1e-6 * area);  // float coordinates
  vtkDataArray* normals = ply->GetPointData()->GetNormals();
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(ply->GetPointData()->GetArray("RGB"));
  ASSERT_NE(normals, nullptr);
  ASSERT_NE(rgb, nullptr);
  ASSERT_EQ(rgb->GetNumberOfComponents(), 3);
  for (int v = 0; v < surface.vertex_count(); ++v) {
    double p[3];
    ply->GetPoint(v, p);
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(p[k], in_sheet_units(surface.V(v, k), k), 1e-6 * kArcsSheet)
          << "vertex " << v << " axis " << k;
      ASSERT_NEAR(normals->GetComponent(v, k), surface.N(v, k), 1e-6) << "vertex " << v;
    }
    const vis::Rgb8 c = bytes(vis::patch_colour(surface.vertex_patch[v]));
    for (int k = 0; k < 3; ++k) ASSERT_EQ(rgb->GetValue(3 * v + k), c[k]) << "vertex " << v;
  }
}

TEST_F(SurfaceFileTest, UnwritablePathIsAnOutputErrorNamingIt) {
  for (auto format : {vis::SurfaceFormat::kObj, vis::SurfaceFormat::kPly}) {
    const std::string path = dir + "/no/such/dir/surface." + enum_name(format);
    try {
      vis::write_surface_file(format, surface, m.fine, vis::Layer::kPatches, arrays, path);
      ADD_FAILURE() << path << " written";
    } catch (const OutputError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
}

// The colour of each surface vertex that is a mesh vertex (weight 1) is the colour the renderer's
// lookup table gives that vertex's value of the layer's array.
void expect_renderer_colours(vis::Layer layer, const char* array, const TrimmedSurface& surface,
                             const MeshArrays& arrays) {
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  vis::Scene scene(arcs_model(), renderer);
  scene.update(arcs_standard_state());
  scene.set_layer(layer, true);
  auto* bar = vtkScalarBarActor::SafeDownCast(scene.legend_prop(layer));
  ASSERT_NE(bar, nullptr);
  vtkScalarsToColors* lut = bar->GetLookupTable();
  vtkDataArray* values = scene.layer_data(layer)->GetPointData()->GetArray(array);
  ASSERT_NE(values, nullptr) << array;
  const std::vector<vis::Rgb8> colours = vis::surface_colours(layer, surface, arrays);
  ASSERT_EQ(colours.size(), static_cast<size_t>(surface.vertex_count()));
  int checked = 0;
  std::set<std::array<int, 3>> distinct;
  for (int v = 0; v < surface.vertex_count(); ++v) {
    if (surface.weight(v, 0) != 1) continue;
    const unsigned char* rgba = lut->MapValue(values->GetTuple1(surface.source(v, 0)));
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(colours[v][k], rgba[k]) << enum_name(layer) << " vertex " << v;
    distinct.insert({rgba[0], rgba[1], rgba[2]});
    ++checked;
  }
  EXPECT_GT(checked, surface.vertex_count() / 2);
  EXPECT_GT(distinct.size(), 10u) << enum_name(layer)
                                  << ": the state should show more than a few colours";
}

TEST_F(SurfaceFileTest, ScalarColoursAreTheRenderers) {
  expect_renderer_colours(vis::Layer::kDogResidual, "log10_dog_residual", surface, arrays);
  expect_renderer_colours(vis::Layer::kBending, "bending", surface, arrays);
}

TEST_F(SurfaceFileTest, CategoricalColoursAreThePalettes) {
  const auto types = vis::surface_colours(vis::Layer::kVertexTypes, surface, arrays);
  const auto patches = vis::surface_colours(vis::Layer::kPatches, surface, arrays);
  for (int v = 0; v < surface.vertex_count(); ++v) {
    EXPECT_EQ(patches[v], bytes(vis::patch_colour(surface.vertex_patch[v]))) << v;
    if (surface.weight(v, 0) == 1) {
      EXPECT_EQ(types[v], bytes(vis::vertex_type_colour(m.map.fine_type[surface.source(v, 0)])))
          << v;
    }
  }
  EXPECT_THROW(vis::surface_colours(vis::Layer::kHandles, surface, arrays), std::logic_error);
}

// Edge strain is one value per quad: a vertex takes the mean over its triangles, coloured through
// the renderer's table (here every quad has the same strain, the table's top colour).
TEST_F(SurfaceFileTest, EdgeStrainColoursAreTheRenderers) {
  vis::SceneState state = arcs_standard_state();
  std::fill(state.fields.edge_strain.begin(), state.fields.edge_strain.end(), 0.25);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  vis::Scene scene(m, renderer);
  scene.update(state);
  scene.set_layer(vis::Layer::kEdgeStrain, true);
  auto* bar = vtkScalarBarActor::SafeDownCast(scene.legend_prop(vis::Layer::kEdgeStrain));
  ASSERT_NE(bar, nullptr);
  const unsigned char* top = bar->GetLookupTable()->MapValue(0.25);
  const auto colours =
      vis::surface_colours(vis::Layer::kEdgeStrain, surface, vis::frame_arrays(m, state.fields));
  for (int v = 0; v < surface.vertex_count(); ++v)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(colours[v][k], top[k]) << "vertex " << v;
}

}  // namespace
}  // namespace sdog
