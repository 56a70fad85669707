#pragma once
// DOG meshes and curves as VTK data sets with named arrays, and VTK XML files.
#include <vtkDataArray.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/surface/mesh_arrays.h"
#include "geometry/surface/trimmed_surface.h"

namespace sdog::vis {

using Polyline3 = std::vector<Eigen::Vector3d>;

/// Quad mesh (n x 3 positions, quads) with the given point and cell arrays.
vtkSmartPointer<vtkUnstructuredGrid> quad_grid(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& F,
                                               const MeshArrays& arrays);

/// The trimmed surface (geometry/surface/trimmed_surface.h) as triangles with its normals
/// ("Normals", the point normals for smooth shading) and the given arrays (trimmed_arrays: one
/// value per surface vertex and per triangle).
vtkSmartPointer<vtkPolyData> triangle_surface(const TrimmedSurface& surface,
                                              const MeshArrays& arrays);

/// Polylines (one cell each; closed ones repeat their first point) with one cell array per entry
/// of `cell_arrays` (values per polyline).
vtkSmartPointer<vtkPolyData> polylines(const std::vector<Polyline3>& lines,
                                       const std::vector<NamedArray>& cell_arrays);

/// Replaces (or adds) the double array `name` of the attributes, reusing its storage.
void set_double_array(vtkDataSetAttributes* attributes, const char* name,
                      const std::vector<double>& values);

/// A 3-component array with one tuple per row of `rows` (a point array of vectors).
vtkSmartPointer<vtkDataArray> vector_array(const std::string& name, const Eigen::MatrixX3d& rows);

/// VTK XML writers; throw OutputError with the path and VTK's reason on failure.
void write_vtu(vtkUnstructuredGrid* grid, const std::string& path);
void write_vtp(vtkPolyData* poly, const std::string& path);
/// After a VTK writer ran: unless it succeeded (`written`), throws OutputError "PATH: cannot write
/// WHAT (VTK's reason)".
void check_written(bool written, const std::string& path, const std::string& what);

/// Reads a VTK XML unstructured grid (.vtu); throws InputError naming the path when the file is
/// missing or not one (with VTK's reason).
vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::string& path);

/// Collects VTK's own error messages instead of letting VTK print them; returns and clears the
/// last one. Installed on first use.
std::string take_vtk_error();

}  // namespace sdog::vis
