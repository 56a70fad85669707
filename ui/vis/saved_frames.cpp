#include "ui/vis/saved_frames.h"

#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "base/errors.h"
#include "base/text_format.h"
#include "ui/vis/vtk_meshes.h"

namespace sdog::vis {
namespace {

// An integer time step ("10", also "10.0"); nullopt for anything else.
std::optional<int> integer_step(const char* text) {
  if (!text) return std::nullopt;
  try {
    size_t used = 0;
    const double value = std::stod(text, &used);
    if (used != std::string(text).size() || value != std::floor(value) || value < 0 || value > 1e9)
      return std::nullopt;
    return static_cast<int>(value);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

Eigen::MatrixX3d rows_of(vtkDataArray* a) {
  Eigen::MatrixX3d out(a->GetNumberOfTuples(), 3);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int k = 0; k < 3; ++k) out(i, k) = a->GetComponent(i, k);
  return out;
}

}  // namespace

std::vector<FrameEntry> read_frame_list(const std::string& pvd_path) {
  if (!std::filesystem::is_regular_file(pvd_path))
    throw InputError(pvd_path +
                     (std::filesystem::exists(pvd_path) ? ": not a file" : ": no such file"));
  take_vtk_error();  // installs the capturing output window
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  parser->SetFileName(pvd_path.c_str());
  const bool parsed = parser->Parse() == 1;
  take_vtk_error();
  vtkXMLDataElement* root = parsed ? parser->GetRootElement() : nullptr;
  vtkXMLDataElement* collection = root ? root->FindNestedElementWithName("Collection") : nullptr;
  if (!collection)
    throw InputError(
        pvd_path +
        ": not a ParaView collection of frames (expected <VTKFile type=\"Collection\"> "
        "with a <Collection>, as sdog run writes frames.pvd)");
  const std::filesystem::path dir = std::filesystem::path(pvd_path).parent_path();
  std::vector<FrameEntry> frames;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    const std::optional<int> step = integer_step(e->GetAttribute("timestep"));
    const char* file = e->GetAttribute("file");
    if (!step || !file || !*file)
      throw InputError(pvd_path + ": <DataSet> " + std::to_string(i + 1) +
                       ": expected a timestep that is an iteration (0, 1, ...) and a file");
    const std::filesystem::path p(file);
    frames.push_back({*step, (p.is_relative() ? dir / p : p).string()});
  }
  if (frames.empty()) throw InputError(pvd_path + ": lists no frames");
  return frames;
}

std::string describe_iterations(const std::vector<int>& its) {
  // An arithmetic series of at least three, possibly followed by one iteration off its stride (a
  // run's last frame).
  auto series_of = [&](size_t n) {
    const int stride = its[1] - its[0];
    bool regular = n >= 3 && stride > 0;
    for (size_t i = 1; regular && i < n; ++i) regular = its[i] - its[i - 1] == stride;
    return regular ? stride : 0;
  };
  for (const size_t n : {its.size(), its.size() - 1}) {
    if (n < 3) break;
    if (const int stride = series_of(n)) {
      std::string text = std::to_string(its.front()) + " to " + std::to_string(its[n - 1]) +
                         " every " + std::to_string(stride);
      return n < its.size() ? text + ", and " + std::to_string(its.back()) : text;
    }
  }
  std::vector<std::string> parts;
  const size_t n = its.size();
  for (size_t i = 0; i < n; ++i) {
    if (n > 12 && i == 5) {
      parts.push_back("... (" + std::to_string(n - 10) + " more)");
      i = n - 6;
      continue;
    }
    parts.push_back(std::to_string(its[i]));
  }
  return join(parts, ", ");
}

FrameEntry find_frame(const std::vector<FrameEntry>& frames, std::optional<int> iteration,
                      const std::string& pvd_path) {
  if (!iteration) return frames.back();
  for (const FrameEntry& f : frames)
    if (f.iteration == *iteration) return f;
  std::vector<int> saved;
  for (const FrameEntry& f : frames) saved.push_back(f.iteration);
  throw InputError(pvd_path + ": no frame of iteration " + std::to_string(*iteration) +
                   "; the saved iterations are " + describe_iterations(saved));
}

SavedFrame read_frame(const std::string& path) {
  const auto grid = read_vtu(path);
  SavedFrame frame;
  vtkPoints* points = grid->GetPoints();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  if (n == 0) throw InputError(path + ": the frame has no points");
  frame.positions.resize(n, 3);
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3];
    points->GetPoint(i, p);
    frame.positions.row(i) << p[0], p[1], p[2];
  }
  if (!frame.positions.allFinite())
    throw InputError(path + ": the frame has positions that are not finite numbers");
  frame.quads.resize(grid->GetNumberOfCells(), 4);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    grid->GetCellPoints(c, count, ids);
    if (grid->GetCellType(c) != VTK_QUAD || count != 4)
      throw InputError(path + ": cell " + std::to_string(c) +
                       " is not a quad: not a frame of a DOG");
    for (int k = 0; k < 4; ++k) frame.quads(c, k) = static_cast<int>(ids[k]);
  }
  vtkDataArray* rest = grid->GetPointData()->GetArray("rest_position");
  if (rest && rest->GetNumberOfComponents() == 3 && rest->GetNumberOfTuples() == n)
    frame.rest = rows_of(rest);
  return frame;
}

void check_frame_of(const SavedFrame& frame, const DogMesh& fine, const std::string& frame_path,
                    const std::string& model_name) {
  const std::string head = frame_path + " is not a frame of " + model_name + ": ";
  if (frame.positions.rows() != fine.vertex_count())
    throw InputError(head + "it has " + std::to_string(frame.positions.rows()) +
                     " vertices, that fine mesh " + std::to_string(fine.vertex_count()));
  if (frame.quads.rows() != fine.quad_count() || frame.quads != fine.F)
    throw InputError(head + "its quads are not those of that fine mesh (" +
                     std::to_string(frame.quads.rows()) + " quads, that mesh " +
                     std::to_string(fine.quad_count()) + ")");
  if (!frame.rest) return;
  const double size = (fine.V.colwise().maxCoeff() - fine.V.colwise().minCoeff()).maxCoeff();
  Eigen::Index worst = 0;
  const double gap = (*frame.rest - fine.V).rowwise().norm().maxCoeff(&worst);
  if (gap > 1e-9 * std::max(size, 1.0))
    throw InputError(
        head + "its rest positions differ (vertex " + std::to_string(worst) + " rests at " +
        format_point(frame.rest->row(worst).head<2>().transpose()) + ", in that mesh at " +
        format_point(fine.V.row(worst).head<2>().transpose()) +
        "): another pattern file or other mesh options (--flatness, --merge-tol, --snap-tol)");
}

}  // namespace sdog::vis
