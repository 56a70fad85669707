#include "ui/vis/model_files.h"
#include <limits>

#include <vtkPointData.h>

#include "geometry/surface/mesh_arrays.h"
#include "ui/vis/vtk_meshes.h"

namespace sdog::vis {
namespace {

Polyline3 lifted(const DogMesh& mesh, const Polyline2& sheet_points, bool closed) {
  Polyline3 out;
  for (const auto& p : sheet_points) {
    const Eigen::Vector2d m = mesh.to_mesh(p);
    out.emplace_back(m.x(), m.y(), 0.0);
  }
  if (closed && !out.empty()) out.push_back(out.front());
  return out;
}

// Per point of the crease polylines (closed ones repeat their first point): 1 where the coarse
// curve has it, 0 where it is interpolated between two coarse points, -1 where it cannot be.
std::vector<double> coarse_points(const DogModel& model) {
  std::vector<double> out;
  const CreaseStitching& st = model.fine.stitching;
  for (size_t k = 0; k < st.curves.size(); ++k) {
    const auto& curve = model.map.curves[k];
    for (const auto& p : curve) out.push_back(p.coarse >= 0 ? 1 : p.segment >= 0 ? 0 : -1);
    if (st.curves[k].closed && !curve.empty()) out.push_back(out[out.size() - curve.size()]);
  }
  return out;
}

}  // namespace

void write_model_files(const DogModel& model, OutputSet& out) {
  write_vtu(quad_grid(model.fine.V, model.fine.F, fine_mesh_arrays(model)),
            out.temporary("fine.vtu"));
  if (model.has_coarse)
    write_vtu(quad_grid(model.coarse.V, model.coarse.F, coarse_mesh_arrays(model)),
              out.temporary("coarse.vtu"));

  const CreaseStitching& st = model.fine.stitching;
  std::vector<Polyline3> creases;
  NamedArray index{"crease", {}, true}, closed{"closed", {}, true},
      assignment{"assignment", {}, true}, angle{"angle", {}, true};
  for (size_t k = 0; k < st.curves.size(); ++k) {
    Polyline3 line;
    for (int p : st.curves[k].points)
      line.emplace_back(st.points[p].flat.x(), st.points[p].flat.y(), 0.0);
    if (st.curves[k].closed && !line.empty()) line.push_back(line.front());
    creases.push_back(std::move(line));
    index.values.push_back(static_cast<double>(k));
    closed.values.push_back(st.curves[k].closed);
    const Crease& c = model.clean.creases[k];
    assignment.values.push_back(static_cast<double>(c.fold));
    angle.values.push_back(c.angle ? fold_sign(c.fold) * *c.angle
                                   : std::numeric_limits<double>::quiet_NaN());
  }
  auto crease_lines = polylines(creases, {index, closed, assignment, angle});
  if (model.has_coarse)
    set_double_array(crease_lines->GetPointData(), "coarse_point", coarse_points(model));
  write_vtp(crease_lines, out.temporary("creases.vtp"));

  std::vector<Polyline3> curves;
  NamedArray kind{"kind", {}, true}, which{"index", {}, true}, fold{"assignment", {}, true};
  const Sheet& sheet = model.pattern.sheet;
  curves.push_back(lifted(model.fine, sheet.outer, true));
  kind.values.push_back(0), which.values.push_back(0), fold.values.push_back(0);
  for (size_t h = 0; h < sheet.holes.size(); ++h) {
    curves.push_back(lifted(model.fine, sheet.holes[h], true));
    kind.values.push_back(0), which.values.push_back(static_cast<double>(h + 1)),
        fold.values.push_back(0);
  }
  for (size_t k = 0; k < model.pattern.creases.size(); ++k) {
    const Crease& c = model.pattern.creases[k];
    curves.push_back(lifted(model.fine, c.points, c.closed));
    kind.values.push_back(1), which.values.push_back(static_cast<double>(k)),
        fold.values.push_back(static_cast<double>(c.fold));
  }
  write_vtp(polylines(curves, {kind, which, fold}), out.temporary("pattern.vtp"));
}

}  // namespace sdog::vis
