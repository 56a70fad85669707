#include "geometry/surface/mesh_arrays.h"

#include "geometry/mesh/dog_model.h"

namespace sdog {

NamedArray quad_patch(const DogMesh& mesh) {
  NamedArray a{"patch", {}, true};
  for (int q = 0; q < mesh.quad_count(); ++q) a.values.push_back(mesh.vertex_patch[mesh.F(q, 0)]);
  return a;
}

const NamedArray* MeshArrays::find_point(const std::string& name) const {
  for (const auto& a : point)
    if (a.name == name) return &a;
  return nullptr;
}

namespace {

template <class T>
NamedArray integral_array(const std::string& name, const std::vector<T>& values) {
  NamedArray a{name, {}, true};
  a.values.reserve(values.size());
  for (const auto& v : values) a.values.push_back(static_cast<double>(v));
  return a;
}

MeshArrays arrays(const DogMesh& mesh, const QuadTopology& topo,
                  const std::vector<VertexType>& type, const std::vector<int>& partner) {
  MeshArrays out;
  out.point.push_back(integral_array("vertex_type", type));
  out.point.push_back(integral_array("patch", mesh.vertex_patch));
  out.point.push_back(integral_array("partner", partner));
  out.point.push_back(integral_array("vertex_class", topo.vertex_class));
  out.cell.push_back(quad_patch(mesh));
  return out;
}

}  // namespace

MeshArrays fine_mesh_arrays(const DogModel& m) {
  if (!m.has_coarse) {
    MeshArrays out;
    out.point.push_back(integral_array("patch", m.fine.vertex_patch));
    out.point.push_back(integral_array("vertex_class", m.fine_topology.vertex_class));
    out.cell.push_back(quad_patch(m.fine));
    return out;
  }
  return arrays(m.fine, m.fine_topology, m.map.fine_type, m.map.fine_to_coarse);
}

MeshArrays coarse_mesh_arrays(const DogModel& m) {
  return arrays(m.coarse, m.coarse_topology, m.map.coarse_type, m.map.coarse_to_fine);
}

}  // namespace sdog
