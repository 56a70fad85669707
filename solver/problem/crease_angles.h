#pragma once
// The fold angle a state reaches at each fold site, signed as the FOLD format does (and as the
// drawing's assignments, geometry/fold_conventions.h): positive for a valley (both sides of the
// crease rise towards +z, the side the drawing is seen from), negative for a mountain.
//
// At a fold site with crease tangent T (through its neighbouring crease points), each of the two
// edge copies gives the direction u into its patch's own side (the edge from its end beyond the
// crease to its end on the patch's side), perpendicular to T. The fold angle
// is pi minus the angle between the two directions; its sign is that of (u_A + u_B) . n, where n
// is the sum of the two sides' normals T x u, each oriented to +z in the flat rest state.
#include <array>
#include <string>
#include <vector>

#include "solver/problem/scenario.h"
#include "solver/terms/crease_geometry.h"

namespace sdog {

class FoldAngles {
 public:
  explicit FoldAngles(const DogMesh& mesh);
  /// The signed fold angle at sites()[k] in the state x, in degrees.
  double at(size_t k, const Dofs& x) const;
  const std::vector<FoldSite>& sites() const { return sites_; }

 private:
  const DogMesh& mesh_;
  std::vector<FoldSite> sites_;
  /// Per site and copy: +1 or -1, the orientation of T x u at rest.
  std::vector<std::array<double, 2>> orientation_;
  struct Frame {
    Eigen::Vector3d u[2], normal[2];
  };
  /// Needs own_v1_[k].
  Frame frame(size_t k, const Dofs& x) const;
  /// Whether v1 is the end of copy `copy`'s edge on its patch's own side.
  bool own_end_is_v1(const FoldSite& site, int copy) const;
  std::vector<std::array<bool, 2>> own_v1_;
};

/// creases.csv: one row per fold site with its crease curve, the crease's element id, assignment,
/// the scenario's target angle there (empty without one) and the signed angle reached in x.
std::string creases_csv(const DogMesh& mesh, const Scenario& scenario, const Dofs& x);

}  // namespace sdog
