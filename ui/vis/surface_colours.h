#pragma once
// The colours of a colour layer (layers.h) at the vertices of the trimmed surface, for files that
// carry colours (PLY): the colours the renderer gives the same layer on the fine mesh (palette.h,
// colour_maps.h), taken at each surface vertex.
#include <array>
#include <vector>

#include "geometry/surface/mesh_arrays.h"
#include "geometry/surface/trimmed_surface.h"
#include "ui/vis/layers.h"

namespace sdog::vis {

using Rgb8 = std::array<unsigned char, 3>;

/// One colour per vertex of `surface` under the colour layer `layer`, from the fine mesh's arrays
/// (frame_arrays: point arrays vertex_type, dog_residual, bending, cell array edge_strain):
/// - vertex-types: vertex_type_color of the vertex's type (the type of the mesh vertex with the
///   largest weight, trimmed_arrays); kUntypedVertexColor without a vertex_type array (no coarse
///   mesh);
/// - patches: patch_color of the vertex's patch;
/// - dog-residual: dog_residual_lut() of the log10 residual (log10_residuals) interpolated to the
///   vertex, as the renderer interpolates it inside a quad;
/// - bending: sequential_lut over robust_range of the mesh's values, of the interpolated value;
/// - edge-strain: the same for the mesh's edge_strain, of the mean over the vertex's triangles of
///   their quads' values (a vertex has one colour, a quad's strain is one value).
/// Throws std::logic_error for a layer that is not a colour layer or a missing array.
std::vector<Rgb8> surface_colours(Layer layer, const TrimmedSurface& surface,
                                  const MeshArrays& mesh_arrays);

}  // namespace sdog::vis
