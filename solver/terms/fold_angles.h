#pragma once
// The fold angle a state reaches at each fold site, signed as the FOLD format does (and as the
// drawing's assignments, geometry/input/fold_conventions.h): positive for a valley (both sides of
// the crease rise towards +z, the side the drawing is seen from), negative for a mountain.
//
// At a fold site with crease tangent T (fold_site_tangent), each of the two edge copies gives the
// direction u into its patch's own side (the edge from its end beyond the crease to its end on the
// patch's side, own_end_is_v1), perpendicular to T. The fold angle is pi minus the angle between
// the two directions; its sign is that of (u_A + u_B) . n, where n is the sum of the two sides'
// normals T x u, each oriented to +z in the flat rest state. This measures the sheet as it is,
// whatever its edge lengths; the angle term (dihedral_angles.h) targets the same angle.
#include <array>
#include <vector>

#include "solver/terms/crease_geometry.h"

namespace sdog {

class FoldAngles {
 public:
  explicit FoldAngles(const DogMesh& mesh);
  /// The signed fold angle at sites()[k] in the state x, in degrees.
  double at(size_t k, const Dofs& x) const;
  const std::vector<FoldSite>& sites() const { return sites_; }
  /// The index in sites() of the fold site at crease point `point`, or -1.
  int site_of(int point) const {
    return point >= 0 && point < static_cast<int>(site_of_.size()) ? site_of_[point] : -1;
  }

 private:
  const DogMesh& mesh_;
  std::vector<FoldSite> sites_;
  std::vector<int> site_of_;
  /// Per site and copy: whether v1 is the end on the patch's own side, and +1 or -1, the
  /// orientation of T x u at rest.
  std::vector<std::array<bool, 2>> own_v1_;
  std::vector<std::array<double, 2>> orientation_;
  struct Frame {
    Eigen::Vector3d u[2], normal[2];
  };
  Frame frame(size_t k, const Dofs& x) const;
};

}  // namespace sdog
