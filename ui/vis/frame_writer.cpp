#include "ui/vis/frame_writer.h"

#include <vtkPointData.h>

#include <cstdio>

#include "geometry/surface/mesh_arrays.h"
#include "solver/problem/diagnostics.h"
#include "ui/vis/vtk_meshes.h"

namespace sdog::vis {

MeshArrays frame_arrays(const DogModel& model, const DogProblem& problem, const Dofs& x) {
  return frame_arrays(model, fields(problem, x));
}

MeshArrays frame_arrays(const DogModel& model, Fields f) {
  MeshArrays arrays = fine_mesh_arrays(model);
  arrays.point.push_back({"dog_residual", std::move(f.dog_residual), false});
  arrays.point.push_back({"bending", std::move(f.bending), false});
  arrays.point.push_back({"position_residual", std::move(f.position_residual), false});
  arrays.cell.push_back({"edge_strain", std::move(f.edge_strain), false});
  return arrays;
}

void write_frame_vtu(const DogModel& model, const Eigen::MatrixX3d& X, const MeshArrays& arrays,
                     const std::string& path) {
  auto grid = quad_grid(X, model.fine.F, arrays);
  grid->GetPointData()->AddArray(vector_array("rest_position", model.fine.V));
  write_vtu(grid, path);
}

FrameWriter::FrameWriter(const DogModel& model, const DogProblem& problem, OutputSet& out,
                         int every, int last_iteration)
    : model_(model),
      problem_(problem),
      out_(out),
      every_(std::max(1, every)),
      last_(last_iteration) {}

void FrameWriter::write_start(const Dofs& x) {
  write(0, x);
}

void FrameWriter::on_iteration(const IterationReport& report, const Dofs& x) {
  if (report.iteration % every_ == 0 || report.iteration == last_ || report.step.failed)
    write(report.iteration, x);
}

void FrameWriter::write(int iteration, const Dofs& x) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.vtu", iteration);
  const Eigen::MatrixX3d X = to_positions(x);
  const MeshArrays arrays = frame_arrays(model_, problem_, x);
  write_frame_vtu(model_, X, arrays, out_.temporary(name));
  frames_.emplace_back(iteration, name);
  if (surfaces_) surfaces_->write_frame(iteration, X, arrays);
}

void FrameWriter::finish() {
  out_.write_text("frames.pvd", pvd_collection(frames_));
}

}  // namespace sdog::vis
