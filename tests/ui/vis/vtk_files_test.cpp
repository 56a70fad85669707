// The VTK files of `sdog mesh --out` read back with VTK's XML readers.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>

#include "base/atomic_output.h"
#include "base/errors.h"
#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "tests/test_support.h"
#include "ui/vis/model_files.h"

namespace sdog {
namespace {

// The reader's output, kept alive beyond the reader.
template <class Reader>
auto read(const std::string& path) {
  auto r = vtkSmartPointer<Reader>::New();
  r->SetFileName(path.c_str());
  r->Update();
  vtkSmartPointer<std::remove_pointer_t<decltype(r->GetOutput())>> out = r->GetOutput();
  return out;
}

TEST(VtkFiles, MeshFilesReadBackWithTheirArrays) {
  const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("crossing_creases.svg")), {21, 21});
  const std::string dir = test::temp_dir("vtk_files");
  OutputSet out(dir);
  vis::write_model_files(m, out);
  const auto files = out.commit();
  ASSERT_EQ(files.size(), 4u);

  auto fine = read<vtkXMLUnstructuredGridReader>(dir + "/fine.vtu");
  ASSERT_EQ(fine->GetNumberOfPoints(), m.fine.vertex_count());
  ASSERT_EQ(fine->GetNumberOfCells(), m.fine.quad_count());
  for (const char* name : {"vertex_type", "patch", "partner", "vertex_class"})
    ASSERT_NE(fine->GetPointData()->GetArray(name), nullptr) << name;
  auto* type = fine->GetPointData()->GetArray("vertex_type");
  auto* partner = fine->GetPointData()->GetArray("partner");
  for (int v = 0; v < m.fine.vertex_count(); ++v) {
    EXPECT_EQ(static_cast<int>(type->GetTuple1(v)), static_cast<int>(m.map.fine_type[v]));
    EXPECT_EQ(static_cast<int>(partner->GetTuple1(v)), m.map.fine_to_coarse[v]);
    double p[3];
    fine->GetPoint(v, p);
    EXPECT_DOUBLE_EQ(p[0], m.fine.V(v, 0));
    EXPECT_DOUBLE_EQ(p[1], m.fine.V(v, 1));
  }

  auto coarse = read<vtkXMLUnstructuredGridReader>(dir + "/coarse.vtu");
  ASSERT_EQ(coarse->GetNumberOfPoints(), m.coarse.vertex_count());
  auto* ctype = coarse->GetPointData()->GetArray("vertex_type");
  int coarse_only = 0;
  for (int v = 0; v < m.coarse.vertex_count(); ++v) coarse_only += ctype->GetTuple1(v) == 3;
  EXPECT_EQ(coarse_only, m.map.coarse_only_count);

  auto creases = read<vtkXMLPolyDataReader>(dir + "/creases.vtp");
  EXPECT_EQ(creases->GetNumberOfCells(), static_cast<vtkIdType>(m.fine.stitching.curves.size()));
  ASSERT_NE(creases->GetCellData()->GetArray("crease"), nullptr);

  auto pattern = read<vtkXMLPolyDataReader>(dir + "/pattern.vtp");
  EXPECT_EQ(pattern->GetNumberOfCells(), static_cast<vtkIdType>(1 + m.pattern.creases.size()));
  ASSERT_NE(pattern->GetCellData()->GetArray("kind"), nullptr);
}

TEST(VtkFiles, FailedWriteLeavesNoFiles) {
  const DogModel m = build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {11, 9});
  const std::string dir = test::temp_dir("vtk_partial");
  {
    OutputSet out(dir);
    vis::write_model_files(m, out);
    // Not committed (as when a later step fails): nothing may remain.
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(VtkFiles, UnwritableDirectoryIsAnOutputError) {
  const std::string dir = test::temp_dir("vtk_unwritable");
  const std::string file = test::write_file(dir, "a_file", "x");
  EXPECT_THROW(OutputSet out(file + "/sub"), OutputError);
}

// A directory where no file can be created although access() allows it (as for root in /proc) is
// refused when the set is made, not when the first file is written.
TEST(VtkFiles, DirectoryWhereNoFileCanBeMadeIsRefusedAtOnce) {
  if (!std::filesystem::is_directory("/proc/self")) GTEST_SKIP() << "no /proc on this machine";
  try {
    OutputSet out("/proc");
    FAIL() << "/proc was accepted as an output directory";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("/proc: the output directory is not writable"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sdog
