#pragma once
// Polygon files read back with a VTK reader, and the area of their triangles, for the tests of
// the files the program writes.
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <Eigen/Geometry>
#include <string>

namespace sdog::test {

/// The output of `Reader` (vtkOBJReader, vtkPLYReader, vtkXMLPolyDataReader, ...) for `path`.
template <class Reader>
vtkSmartPointer<vtkPolyData> read_poly(const std::string& path) {
  auto r = vtkSmartPointer<Reader>::New();
  r->SetFileName(path.c_str());
  r->Update();
  vtkSmartPointer<vtkPolyData> out = r->GetOutput();
  return out;
}

/// Sum of the areas of the polygons, each of which must be a triangle.
inline double triangle_area(vtkPolyData* poly) {
  double area = 0;
  vtkCellArray* polys = poly->GetPolys();
  polys->InitTraversal();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  while (polys->GetNextCell(n, ids)) {
    EXPECT_EQ(n, 3);
    if (n != 3) continue;
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k) poly->GetPoint(ids[k], p[k].data());
    area += 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
  }
  return area;
}

}  // namespace sdog::test
