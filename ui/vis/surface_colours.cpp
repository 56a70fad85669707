#include "ui/vis/surface_colours.h"

#include <vtkLookupTable.h>

#include <cmath>
#include <stdexcept>

#include "geometry/mesh/fine_coarse_map.h"
#include "ui/vis/colour_maps.h"
#include "ui/vis/palette.h"
#include "ui/vis/scene_state.h"

namespace sdog::vis {
namespace {

Rgb8 bytes(const Rgb& c) {
  return {static_cast<unsigned char>(std::lround(255 * c[0])),
          static_cast<unsigned char>(std::lround(255 * c[1])),
          static_cast<unsigned char>(std::lround(255 * c[2]))};
}

const NamedArray* find(const std::vector<NamedArray>& arrays, const std::string& name) {
  for (const auto& a : arrays)
    if (a.name == name) return &a;
  return nullptr;
}

const NamedArray& require(const std::vector<NamedArray>& arrays, const std::string& name) {
  const NamedArray* a = find(arrays, name);
  if (!a) throw std::logic_error("surface colours: the mesh has no array '" + name + "'");
  return *a;
}

// Per surface vertex the mean of a quad array over the vertex's triangles.
std::vector<double> cell_means_at_vertices(const TrimmedSurface& surface,
                                           const std::vector<double>& quad_values) {
  std::vector<double> sum(static_cast<size_t>(surface.vertex_count()), 0.0), count(sum.size(), 0.0);
  for (int t = 0; t < surface.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<size_t>(surface.T(t, k));
      sum[v] += quad_values[static_cast<size_t>(surface.triangle_quad[static_cast<size_t>(t)])];
      count[v] += 1;
    }
  for (size_t v = 0; v < sum.size(); ++v) sum[v] = count[v] > 0 ? sum[v] / count[v] : 0.0;
  return sum;
}

std::vector<Rgb8> mapped(vtkLookupTable* lut, const std::vector<double>& values) {
  std::vector<Rgb8> out;
  out.reserve(values.size());
  for (double v : values) {
    const unsigned char* rgba = lut->MapValue(v);
    out.push_back({rgba[0], rgba[1], rgba[2]});
  }
  return out;
}

// The renderer's colours of a linear layer: from 0 to the 95th percentile of the mesh's values.
std::vector<Rgb8> robust_colours(const std::vector<double>& mesh_values,
                                 const std::vector<double>& surface_values) {
  const auto range = robust_range(mesh_values);
  return mapped(sequential_lut(range[0], range[1]), surface_values);
}

}  // namespace

std::vector<Rgb8> surface_colours(Layer layer, const TrimmedSurface& surface,
                                  const MeshArrays& mesh_arrays) {
  const auto n = static_cast<size_t>(surface.vertex_count());
  std::vector<Rgb8> out;
  switch (layer) {
    case Layer::kVertexTypes: {
      const NamedArray* types = find(mesh_arrays.point, "vertex_type");
      if (!types) return std::vector<Rgb8>(n, bytes(kUntypedVertexColour));
      for (double type : trimmed_point_values(surface, types->values, types->integral))
        out.push_back(bytes(vertex_type_colour(static_cast<VertexType>(std::lround(type)))));
      return out;
    }
    case Layer::kPatches:
      for (int patch : surface.vertex_patch) out.push_back(bytes(patch_colour(patch)));
      return out;
    case Layer::kDogResidual: {
      const NamedArray& residual = require(mesh_arrays.point, "dog_residual");
      return mapped(dog_residual_lut(),
                    trimmed_point_values(surface, log10_residuals(residual.values)));
    }
    case Layer::kBending: {
      const NamedArray& bending = require(mesh_arrays.point, "bending");
      return robust_colours(bending.values, trimmed_point_values(surface, bending.values));
    }
    case Layer::kEdgeStrain: {
      const NamedArray& strain = require(mesh_arrays.cell, "edge_strain");
      return robust_colours(strain.values, cell_means_at_vertices(surface, strain.values));
    }
    default:
      throw std::logic_error(std::string("surface colours: '") + enum_name(layer) +
                             "' is not a colour layer");
  }
}

}  // namespace sdog::vis
