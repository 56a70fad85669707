#include "ui/studio/vertex_inspector.h"

#include <stdexcept>

namespace sdog::studio {
namespace {

QString row(const QString& name, const QString& value) {
  return "<tr><td><b>" + name + "</b></td><td>" + value + "</td></tr>";
}

QString value_at(const std::vector<double>& values, int i) {
  return i < static_cast<int>(values.size()) ? QString::number(values[i], 'g', 4) : QString("-");
}

}  // namespace

QString describe_vertex(const DogModel& model, const vis::SceneState& state, int v) {
  if (v < 0 || v >= model.fine.vertex_count())
    throw std::out_of_range("vertex " + std::to_string(v) + " does not exist (the fine mesh has " +
                            std::to_string(model.fine.vertex_count()) + " vertices)");
  QString html = "<table>";
  html += row("fine vertex", QString::number(v));
  html += row("patch", QString::number(model.fine.vertex_patch[v]));
  html += row("grid (i, j)",
              QString("(%1, %2)").arg(model.fine.grid[v].x()).arg(model.fine.grid[v].y()));
  html += row("class", enum_name(model.fine_topology.vertex_class[v]));
  if (model.has_coarse) {
    html += row("type", enum_name(model.map.fine_type[v]));
    const int twin = model.map.fine_to_coarse[v];
    html += row("coarse twin", twin >= 0 ? QString::number(twin) : QString("none"));
    if (model.map.fine_type[v] == VertexType::kI) {
      const auto& e = model.map.fine_to_coarse_edge[v];
      html += row("on coarse edge", QString("%1 - %2").arg(e[0]).arg(e[1]));
    } else if (model.map.fine_type[v] == VertexType::kX) {
      html += row("centre of coarse quad", QString::number(model.map.fine_to_coarse_quad[v]));
    }
  } else {
    html += row("type", "no coarse mesh (even resolution)");
  }
  if (v < state.fine.rows())
    html += row("position", QString("(%1, %2, %3)")
                                .arg(state.fine(v, 0), 0, 'f', 3)
                                .arg(state.fine(v, 1), 0, 'f', 3)
                                .arg(state.fine(v, 2), 0, 'f', 3));
  html += row("DOG residual", value_at(state.fields.dog_residual, v));
  html += row("bending", value_at(state.fields.bending, v));
  html += row("distance to target", value_at(state.fields.position_residual, v));
  return html + "</table>";
}

}  // namespace sdog::studio
