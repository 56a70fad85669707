#pragma once
// The trimmed surface of a DOG mesh: each patch's quads clipped at the patch's crease curves and
// at the sheet's boundary, triangulated. The quad mesh overhangs at every crease (a patch owns
// every cell it overlaps, whole); the trimmed surface keeps only the part of each cell that lies
// in the patch, so neighbouring patches meet along their crease without overlap, and where the
// stitching holds their common edges coincide.
//
// Every vertex of the trimmed surface is a fixed bilinear combination of the corners of one quad
// (a quad corner, or a point on a quad edge such as a crease point copy), so the topology is built
// once per mesh and a new state only recombines positions. Vertices are shared between the
// triangles of one patch (smooth shading within a patch) and never between patches (a fold is a
// sharp edge).
#include <Eigen/Core>
#include <vector>

#include "geometry/mesh/dog_mesh.h"
#include "geometry/surface/mesh_arrays.h"

namespace sdog {

struct TrimmedSurface {
  Eigen::MatrixX3d V;  ///< positions
  Eigen::MatrixX3d N;  ///< unit vertex normals (area-weighted over the patch's triangles)
  Eigen::MatrixX3i T;  ///< triangles, counter-clockwise seen from +z at rest
  std::vector<int> triangle_quad;  ///< the quad each triangle lies in
  std::vector<int> vertex_patch;   ///< the patch of each vertex
  /// Vertex r is sum_k weight(r, k) * X(source(r, k)) (bilinear in its quad; unused entries have
  /// weight 0).
  Eigen::MatrixX4i source;
  Eigen::MatrixX4d weight;

  int vertex_count() const { return static_cast<int>(V.rows()); }
  int triangle_count() const { return static_cast<int>(T.rows()); }
};

/// The trimmed surface of `mesh` at positions X (n x 3; the rest state is mesh.V).
TrimmedSurface trimmed_surface(const DogMesh& mesh, const Eigen::MatrixX3d& X);

/// Moves the surface to positions X of its mesh: new V and N, same topology.
void place_trimmed_surface(TrimmedSurface& surface, const Eigen::MatrixX3d& X);

/// One per-vertex array of the mesh at the surface's vertices: interpolated with the vertices'
/// weights, or (integral) the value of the source with the largest weight.
std::vector<double> trimmed_point_values(const TrimmedSurface& surface,
                                         const std::vector<double>& values, bool integral = false);
/// One per-quad array of the mesh on the surface's triangles (each its quad's value).
std::vector<double> trimmed_cell_values(const TrimmedSurface& surface,
                                        const std::vector<double>& values);

/// The mesh's arrays carried over to the surface: a point array interpolated with the vertices'
/// weights (an integral one takes the value of the source with the largest weight), a cell array
/// copied from each triangle's quad.
MeshArrays trimmed_arrays(const TrimmedSurface& surface, const MeshArrays& mesh_arrays);

/// Total area of the triangles.
double surface_area(const TrimmedSurface& surface);

}  // namespace sdog
