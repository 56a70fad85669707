// The trimmed surface files of `sdog run --out` as a user opens them: surface.pvd read the way
// ParaView reads a collection (its XML, then every listed .vtp), and the --export OBJ and PLY files
// read back with VTK's readers against the .vtp of the same frame (triangles, area, sheet units,
// normals, colours); bad --export values and an unwritable output directory.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "tests/app/run_sdog.h"
#include "tests/vtk_read_back.h"

namespace sdog {
namespace {

namespace fs = std::filesystem;

// one_curve.svg is a 600 x 400 sheet (viewBox 0 0 600 400; y negated: from -400 to 0). At 21x15
// grid lines a grid column is 600 / 20 sheet units wide: mesh units are sheet units * 20 / 600.
const std::string kPattern = test::dataset("one_curve.svg");
constexpr double kWidth = 600, kHeight = 400, kScale = 20.0 / 600;
const std::string kRun = "run '" + kPattern + "' --res 21x15 --iters 20 --hold 5 -q";

using test::read_poly;
using test::triangle_area;

// (timestep, file) of every DataSet of a .pvd collection, as ParaView's collection reader sees it.
std::vector<std::pair<int, std::string>> collection(const std::string& pvd) {
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  parser->SetFileName(pvd.c_str());
  EXPECT_EQ(parser->Parse(), 1) << pvd;
  std::vector<std::pair<int, std::string>> out;
  vtkXMLDataElement* root = parser->GetRootElement();
  if (!root) return out;
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* c = root->FindNestedElementWithName("Collection");
  if (!c) {
    ADD_FAILURE() << pvd << ": no Collection";
    return out;
  }
  for (int i = 0; i < c->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = c->GetNestedElement(i);
    EXPECT_STREQ(e->GetName(), "DataSet");
    out.emplace_back(std::atoi(e->GetAttribute("timestep")), e->GetAttribute("file"));
  }
  return out;
}

std::string numbered(const std::string& stem, int iteration, const std::string& ext) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%04d.%s", stem.c_str(), iteration, ext.c_str());
  return name;
}

struct SurfaceExportTest : ::testing::Test {
  static std::string dir;
  static test::Run run;
  static void SetUpTestSuite() {
    dir = test::temp_dir("surface_export") + "/out";
    run = test::run_sdog(
        kRun + " --frames-every 10 --export obj,ply --export-colour bending --out " + dir);
  }
  void SetUp() override { ASSERT_EQ(run.code, 0) << run.err; }
};
std::string SurfaceExportTest::dir;
test::Run SurfaceExportTest::run;

TEST_F(SurfaceExportTest, SurfacePvdListsTheFramesSurfacesWithArraysAndNormals) {
  const auto frames = collection(dir + "/frames.pvd");
  const auto surfaces = collection(dir + "/surface.pvd");
  ASSERT_EQ(surfaces.size(), frames.size());
  ASSERT_EQ(surfaces.size(), 4u);  // iterations 0, 10, 20 and the last, 25
  for (size_t i = 0; i < surfaces.size(); ++i) {
    const auto& [step, file] = surfaces[i];
    EXPECT_EQ(step, frames[i].first);
    EXPECT_EQ(file, numbered("surface", step, "vtp"));
    const std::string path = dir + "/" + file;
    ASSERT_TRUE(fs::exists(path)) << path;
    const auto poly = read_poly<vtkXMLPolyDataReader>(path);
    ASSERT_GT(poly->GetNumberOfPolys(), 0) << path;
    EXPECT_EQ(poly->GetNumberOfPolys(), poly->GetNumberOfCells()) << path << ": only triangles";
    for (const char* name :
         {"dog_residual", "bending", "position_residual", "patch", "vertex_type", "vertex_class"}) {
      vtkDataArray* a = poly->GetPointData()->GetArray(name);
      ASSERT_NE(a, nullptr) << path << ": point array " << name;
      EXPECT_EQ(a->GetNumberOfTuples(), poly->GetNumberOfPoints()) << name;
    }
    for (const char* name : {"patch", "edge_strain"}) {
      vtkDataArray* a = poly->GetCellData()->GetArray(name);
      ASSERT_NE(a, nullptr) << path << ": cell array " << name;
      EXPECT_EQ(a->GetNumberOfTuples(), poly->GetNumberOfCells()) << name;
    }
    vtkDataArray* normals = poly->GetPointData()->GetNormals();
    ASSERT_NE(normals, nullptr) << path;
    EXPECT_STREQ(normals->GetName(), "Normals");
    ASSERT_EQ(normals->GetNumberOfComponents(), 3);
    for (vtkIdType p = 0; p < normals->GetNumberOfTuples(); ++p) {
      const double* n = normals->GetTuple3(p);
      ASSERT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1, 1e-9)
          << path << " point " << p;
    }
  }
  // The flat start lies in z = 0 and fills the sheet: its area is the sheet's, in mesh units.
  const auto start = read_poly<vtkXMLPolyDataReader>(dir + "/surface_0000.vtp");
  double b[6];
  start->GetBounds(b);
  EXPECT_NEAR(b[4], 0, 1e-12);
  EXPECT_NEAR(b[5], 0, 1e-12);
  EXPECT_NEAR(triangle_area(start), kWidth * kHeight * kScale * kScale,
              1e-9 * kWidth * kHeight * kScale * kScale);
}

TEST_F(SurfaceExportTest, ObjAndPlyMatchTheVtpOfTheirFrameInSheetUnits) {
  for (const auto& [step, file] : collection(dir + "/surface.pvd")) {
    const auto vtp = read_poly<vtkXMLPolyDataReader>(dir + "/" + file);
    const double area = triangle_area(vtp) / (kScale * kScale);  // in sheet units
    const std::string obj_path = dir + "/" + numbered("surface", step, "obj");
    const std::string ply_path = dir + "/" + numbered("surface", step, "ply");
    ASSERT_TRUE(fs::exists(obj_path)) << obj_path;
    ASSERT_TRUE(fs::exists(ply_path)) << ply_path;
    const auto obj = read_poly<vtkOBJReader>(obj_path);
    const auto ply = read_poly<vtkPLYReader>(ply_path);
    for (vtkPolyData* p : {obj.Get(), ply.Get()}) {
      EXPECT_EQ(p->GetNumberOfPolys(), vtp->GetNumberOfPolys()) << "iteration " << step;
      EXPECT_NEAR(triangle_area(p), area, 1e-6 * area) << "iteration " << step;
      ASSERT_NE(p->GetPointData()->GetNormals(), nullptr) << "iteration " << step;
    }
    vtkDataArray* rgb = ply->GetPointData()->GetArray("RGB");
    ASSERT_NE(rgb, nullptr) << ply_path;
    EXPECT_EQ(rgb->GetNumberOfComponents(), 3);
    EXPECT_EQ(rgb->GetDataType(), VTK_UNSIGNED_CHAR);
    // Bending colours: a bent state shows more than one colour.
    if (step > 0) {
      EXPECT_GT(rgb->GetRange(0)[1] - rgb->GetRange(0)[0], 0) << ply_path;
    }

    // Sheet units: the .vtp's bounds, back in sheet units, are the OBJ's (VTK's OBJ reader keeps
    // float coordinates).
    double vb[6], ob[6];
    vtp->GetBounds(vb);
    obj->GetBounds(ob);
    const double origin[3] = {0, -kHeight, 0};
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(ob[k], vb[k] / kScale + origin[k / 2], 1e-6 * kWidth)
          << "iteration " << step << " bound " << k;
    if (step == 0) {
      const double sheet[6] = {0, kWidth, -kHeight, 0, 0, 0};
      for (int k = 0; k < 6; ++k) EXPECT_NEAR(ob[k], sheet[k], 1e-6 * kWidth) << "bound " << k;
    }
  }
  // The final state's files are those of the last frame.
  EXPECT_EQ(test::slurp(dir + "/surface.obj"), test::slurp(dir + "/surface_0025.obj"));
  EXPECT_EQ(test::slurp(dir + "/surface.ply"), test::slurp(dir + "/surface_0025.ply"));
  EXPECT_NE(run.out.find("surface.pvd and 4 surface_NNNN.vtp"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("surface.obj and 4 surface_NNNN.obj, surface.ply and 4 surface_NNNN.ply"),
            std::string::npos)
      << run.out;
}

TEST(SurfaceExport, WithoutFramesOnlyTheFinalState) {
  const std::string dir = test::temp_dir("surface_final") + "/out";
  const auto r = test::run_sdog(kRun + " --frames-every 0 --export ply --out " + dir);
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> surfaces;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind("surface", 0) == 0)
      surfaces.push_back(e.path().filename().string());
  EXPECT_EQ(surfaces, std::vector<std::string>{"surface.ply"});
  const auto ply = read_poly<vtkPLYReader>(dir + "/surface.ply");
  EXPECT_GT(ply->GetNumberOfPolys(), 0);
  EXPECT_NE(ply->GetPointData()->GetArray("RGB"), nullptr);
}

TEST(SurfaceExport, BadValuesAreUsageErrorsBeforeAnyOutput) {
  const std::string dir = test::temp_dir("surface_bad");
  struct Case {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      {"--export stl --out " + dir + "/a",
       "--export: unknown format 'stl' (known: obj, ply, fold)"},
      {"--export obj,obj --out " + dir + "/a", "--export: format 'obj' is listed twice"},
      {"--export obj,,ply --out " + dir + "/a", "--export: unknown format ''"},
      {"--export obj", "--export writes into the --out directory"},
      {"--export ply --export-colour handles --out " + dir + "/a",
       "--export-colour: 'handles' is not a colour layer"},
      {"--export obj --export-colour bending --out " + dir + "/a",
       "--export-colour colours the PLY files"},
  };
  for (const auto& c : cases) {
    const auto r = test::run_sdog(kRun + " " + c.args);
    EXPECT_EQ(r.code, 2) << c.args << ": " << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir + "/a")) << c.args;
  }
}

TEST(SurfaceExport, UnwritableOutputLeavesNothing) {
  test::expect_unwritable_output_fails(kRun + " --export obj,ply", "surface_unwritable");
}

}  // namespace
}  // namespace sdog
