#include "ui/vis/frame_writer.h"

#include <vtkPointData.h>

#include <cstdio>

#include "geometry/mesh_arrays.h"
#include "solver/problem/diagnostics.h"
#include "ui/vis/vtk_meshes.h"

namespace sdog::vis {

MeshArrays frame_arrays(const DogModel& model, const DogProblem& problem, const Dofs& x) {
  MeshArrays arrays = fine_mesh_arrays(model);
  Fields f = fields(problem, x);
  arrays.point.push_back({"dog_residual", std::move(f.dog_residual), false});
  arrays.point.push_back({"bending", std::move(f.bending), false});
  arrays.point.push_back({"position_residual", std::move(f.position_residual), false});
  arrays.cell.push_back({"edge_strain", std::move(f.edge_strain), false});
  return arrays;
}

FrameWriter::FrameWriter(const DogModel& model, const DogProblem& problem, OutputSet& out, int every,
                         int last_iteration)
    : model_(model), problem_(problem), out_(out), every_(std::max(1, every)), last_(last_iteration) {}

void FrameWriter::write_start(const Dofs& x) { write(0, x); }

void FrameWriter::on_iteration(const IterationReport& report, const Dofs& x) {
  if (report.iteration % every_ == 0 || report.iteration == last_ || report.step.failed) write(report.iteration, x);
}

void FrameWriter::write(int iteration, const Dofs& x) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.vtu", iteration);
  auto grid = quad_grid(to_positions(x), model_.fine.F, frame_arrays(model_, problem_, x));
  grid->GetPointData()->AddArray(vector_array("rest_position", model_.fine.V));
  write_vtu(grid, out_.temporary(name));
  frames_.emplace_back(iteration, name);
}

void FrameWriter::finish() {
  std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const auto& [iteration, name] : frames_)
    pvd += "    <DataSet timestep=\"" + std::to_string(iteration) + "\" group=\"\" part=\"0\" file=\"" + name + "\"/>\n";
  pvd += "  </Collection>\n</VTKFile>\n";
  out_.write_text("frames.pvd", pvd);
}

}  // namespace sdog::vis
