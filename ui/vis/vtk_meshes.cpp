#include "ui/vis/vtk_meshes.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyLine.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <filesystem>
#include <mutex>

#include "base/errors.h"

namespace sdog::vis {
namespace {

// Keeps VTK's messages for our exceptions instead of printing them.
class CapturingOutputWindow : public vtkOutputWindow {
 public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override {
    std::lock_guard<std::mutex> lock(mutex_);
    last_ = text ? text : "";
  }
  std::string take() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::string s;
    s.swap(last_);
    return s;
  }

 private:
  std::mutex mutex_;
  std::string last_;
};
vtkStandardNewMacro(CapturingOutputWindow);

CapturingOutputWindow* output_window() {
  static vtkSmartPointer<CapturingOutputWindow> window = [] {
    auto w = vtkSmartPointer<CapturingOutputWindow>::New();
    vtkOutputWindow::SetInstance(w);
    return w;
  }();
  return window;
}

vtkSmartPointer<vtkDataArray> to_vtk(const NamedArray& a) {
  vtkSmartPointer<vtkDataArray> out;
  if (a.integral)
    out = vtkSmartPointer<vtkIntArray>::New();
  else
    out = vtkSmartPointer<vtkDoubleArray>::New();
  out->SetName(a.name.c_str());
  out->SetNumberOfComponents(1);
  out->SetNumberOfTuples(static_cast<vtkIdType>(a.values.size()));
  for (size_t k = 0; k < a.values.size(); ++k)
    out->SetTuple1(static_cast<vtkIdType>(k), a.values[k]);
  return out;
}

std::string one_line(std::string s) {
  for (auto& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

template <class Writer, class Data>
void write_xml(Data* data, const std::string& path) {
  output_window();
  auto writer = vtkSmartPointer<Writer>::New();
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  writer->SetDataModeToAppended();
  writer->SetCompressorTypeToZLib();
  check_written(writer->Write() == 1 && writer->GetErrorCode() == 0, path, "the VTK file");
}

}  // namespace

std::string take_vtk_error() {
  return output_window()->take();
}

vtkSmartPointer<vtkUnstructuredGrid> quad_grid(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& F,
                                               const MeshArrays& arrays) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(V.rows());
  for (Eigen::Index i = 0; i < V.rows(); ++i) points->SetPoint(i, V(i, 0), V(i, 1), V(i, 2));
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->Allocate(F.rows());
  for (Eigen::Index q = 0; q < F.rows(); ++q) {
    const vtkIdType ids[4] = {F(q, 0), F(q, 1), F(q, 2), F(q, 3)};
    grid->InsertNextCell(VTK_QUAD, 4, ids);
  }
  for (const auto& a : arrays.point) grid->GetPointData()->AddArray(to_vtk(a));
  for (const auto& a : arrays.cell) grid->GetCellData()->AddArray(to_vtk(a));
  return grid;
}

void set_double_array(vtkDataSetAttributes* attributes, const char* name,
                      const std::vector<double>& values) {
  auto* array = vtkDoubleArray::SafeDownCast(attributes->GetArray(name));
  if (!array) {
    auto fresh = vtkSmartPointer<vtkDoubleArray>::New();
    fresh->SetName(name);
    attributes->AddArray(fresh);
    array = fresh;
  }
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (size_t k = 0; k < values.size(); ++k) array->SetValue(static_cast<vtkIdType>(k), values[k]);
  array->Modified();
}

vtkSmartPointer<vtkPolyData> triangle_surface(const TrimmedSurface& surface,
                                              const MeshArrays& arrays) {
  const Eigen::MatrixX3d& V = surface.V;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(V.rows());
  for (Eigen::Index i = 0; i < V.rows(); ++i) points->SetPoint(i, V(i, 0), V(i, 1), V(i, 2));
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->AllocateExact(surface.T.rows(), 3 * surface.T.rows());
  for (Eigen::Index t = 0; t < surface.T.rows(); ++t) {
    const vtkIdType ids[3] = {surface.T(t, 0), surface.T(t, 1), surface.T(t, 2)};
    triangles->InsertNextCell(3, ids);
  }
  auto normals = vtkSmartPointer<vtkDoubleArray>::New();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(V.rows());
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    normals->SetTuple3(i, surface.N(i, 0), surface.N(i, 1), surface.N(i, 2));
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  poly->GetPointData()->SetNormals(normals);
  for (const auto& a : arrays.point) poly->GetPointData()->AddArray(to_vtk(a));
  for (const auto& a : arrays.cell) poly->GetCellData()->AddArray(to_vtk(a));
  return poly;
}

vtkSmartPointer<vtkPolyData> polylines(const std::vector<Polyline3>& lines,
                                       const std::vector<NamedArray>& cell_arrays) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& line : lines) {
    cells->InsertNextCell(static_cast<int>(line.size()));
    for (const auto& p : line) cells->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), p.z()));
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(cells);
  for (const auto& a : cell_arrays) poly->GetCellData()->AddArray(to_vtk(a));
  return poly;
}

vtkSmartPointer<vtkDataArray> vector_array(const std::string& name, const Eigen::MatrixX3d& rows) {
  auto out = vtkSmartPointer<vtkDoubleArray>::New();
  out->SetName(name.c_str());
  out->SetNumberOfComponents(3);
  out->SetNumberOfTuples(rows.rows());
  for (Eigen::Index i = 0; i < rows.rows(); ++i)
    out->SetTuple3(i, rows(i, 0), rows(i, 1), rows(i, 2));
  return out;
}

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError(path + (std::filesystem::exists(path) ? ": not a file" : ": no such file"));
  take_vtk_error();  // installs the capturing output window and forgets older messages
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(path.c_str());
  // CanReadFile first: on a file that is not VTK XML at all, Update() only warns.
  const bool readable = reader->CanReadFile(path.c_str()) != 0;
  if (readable) reader->Update();
  const std::string why = one_line(take_vtk_error());
  if (!readable || reader->GetErrorCode() != 0 || !why.empty() || !reader->GetOutput())
    throw InputError(path + ": not a readable VTK unstructured grid (.vtu) file" +
                     (why.empty() ? "" : " (" + why + ")"));
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->ShallowCopy(reader->GetOutput());  // outlives the reader
  return grid;
}

void check_written(bool written, const std::string& path, const std::string& what) {
  if (written) return;
  const std::string why = one_line(take_vtk_error());
  throw OutputError(path + ": cannot write " + what + (why.empty() ? "" : " (" + why + ")"));
}

void write_vtu(vtkUnstructuredGrid* grid, const std::string& path) {
  write_xml<vtkXMLUnstructuredGridWriter>(grid, path);
}

void write_vtp(vtkPolyData* poly, const std::string& path) {
  write_xml<vtkXMLPolyDataWriter>(poly, path);
}

}  // namespace sdog::vis
