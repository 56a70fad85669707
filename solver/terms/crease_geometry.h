#pragma once
// Geometry along the creases of a (deformed) DOG: neighbouring crease points, tangents, and the
// folding test of the thesis.
#include <vector>

#include "geometry/mesh/dog_mesh.h"
#include "solver/terms/term.h"

namespace sdog {

/// Position of an edge point in x: t p_v1 + (1 - t) p_v2.
Eigen::Vector3d edge_point_position(const EdgePoint& e, const Dofs& x);

/// Position of a crease point (its first copy) in x.
Eigen::Vector3d crease_point_position(const CreaseStitching::Point& point, const Dofs& x);

/// Unit tangent at p of the circle through b, p, f: normalize((p - b)|f - p| + (f - p)|p - b|).
Eigen::Vector3d circle_tangent(const Eigen::Vector3d& b, const Eigen::Vector3d& p,
                               const Eigen::Vector3d& f);

/// An interior crease point where the crease (or seam, not a slit) crosses the inside of a grid
/// edge and exactly two patches meet: the places where folding is tested and biased.
struct FoldSite {
  int curve, index;  ///< position along the curve
  int point;         ///< crease point
  int prev, next;    ///< neighbouring crease points
  /// The nearest crease points along the crease, each way, at least a twentieth of a grid cell
  /// away in the flat state (prev and next when there are none): the crease's direction.
  int chord_prev, chord_next;
  /// The crease is straight there in the rest state (no osculating plane), or assigned flat:
  /// neither the fold test nor the fold bias applies.
  bool flat;
};
std::vector<FoldSite> fold_sites(const DogMesh& mesh);

/// Unit tangent of the crease at a fold site in the state x: the circle through the site's crease
/// point and its two neighbours, oriented from the previous point to the next.
Eigen::Vector3d fold_site_tangent(const DogMesh& mesh, const FoldSite& site, const Dofs& x);

/// Whether end v1 of copy `copy`'s crossing edge lies on its patch's own side of the crease (a
/// patch reaches a cell or two beyond its creases; its own side is where its trimmed piece of a
/// cell on the edge runs from the crease point, in the flat rest state).
bool own_end_is_v1(const DogMesh& mesh, const FoldSite& site, int copy);

struct FoldCheck {
  bool folded = true;
  int checked = 0;  ///< sites tested
  int violations =
      0;  ///< sites where both edge copies lie on the same side of the osculating plane
};

/// The thesis's folding test: at every fold site with 0.05 <= t <= 0.95, not flat at rest, the
/// crease not (nearly) parallel to the edge (|cos| <= 0.9995) and curvature >= 1e-5, the two
/// copies e1, e2 of the crossing edge must lie on opposite sides of the osculating plane,
/// B.e1 * B.e2 <= 0 with B = (p - p_prev) x (p_next - p); that is, the two half-edges leaving the
/// crease into their own patches are on the same side of the plane.
FoldCheck check_folded(const DogMesh& mesh, const std::vector<FoldSite>& sites, const Dofs& x);

}  // namespace sdog
