#pragma once
// Signed dihedral angles at fold sites (soft). At a fold site the crease crosses a grid edge; the
// edge has one copy in each of the two patches, with unit directions a = (a1 - a2) / |a1 - a2| and
// b = (b1 - b2) / |b1 - b2|, and the crease has the unit tangent T (the circle through the crease
// point and its two neighbours along the crease). Folding the crease by the dihedral angle theta
// (0 flat, positive valley, negative mountain, as FOLD signs it) turns the copies apart so that,
// with alpha the angle between crease and edge in the flat sheet,
//   c = a . b                   = cos^2(alpha) + sin^2(alpha) cos(theta)
//   s = sigma (a x b) . T       =                sin^2(alpha) sin(theta)
// where sigma = +1 or -1 orients each site so that valleys give positive s. The two residual rows
// are c and s minus their values at the target angle: (c - cos^2 alpha, s) runs once around a
// circle of radius sin^2(alpha) as theta runs over (-180, 180] degrees, so the residual vanishes
// only at the target angle itself. The mirror image of a fold (-theta) is no minimum, and targets
// beyond 90 degrees are told apart from their supplements. The cosine row alone, the thesis's
// form, is even in theta.
//
// The edges enter as unit vectors: the thesis divides by their rest lengths instead, which lets a
// site far from its target lower the term by shrinking its edges towards (c, s) = (0, 0), the
// circle's centre, against nothing but the soft isometry.
//
// Gauss-Newton Hessian only.
#include <array>
#include <vector>

#include "solver/terms/crease_geometry.h"
#include "solver/terms/term.h"

namespace sdog {

/// What an angle constraint needs of its fold site, from the flat rest state.
struct DihedralSite {
  int point = -1;  ///< the crease point
  /// a1, a2 (copy A's edge; the crease point is t[0] a1 + (1 - t[0]) a2), b1, b2 (copy B's edge),
  /// then the edges of the previous and the next crease point along the crease.
  std::array<int, 8> vertices{};
  std::array<double, 3> t{};  ///< of the crease point, the previous and the next one
  double alpha = 0;           ///< angle between crease tangent and grid edge (radians)
  double orientation = 1;     ///< sigma
};
/// The site's geometry in the mesh's flat rest state.
DihedralSite dihedral_site(const DogMesh& mesh, const FoldSite& site);

/// The sites across seams (crease_pattern.h) at their crease points on grid vertices, where a seam
/// that runs along a grid line crosses no grid edge and so has no fold site: each patch's copy of
/// the vertex with its grid neighbour on the patch's own side, across the seam (copy A's edge from
/// its neighbour to the vertex, t = 0; copy B's from the vertex to its neighbour, so that the two
/// edges are parallel in the flat sheet), alpha 90 degrees. An angle target of zero there keeps
/// the paper smooth across the seam. Points whose sides cannot be told apart (a patch with
/// neighbours on both sides, near the seam's ends) have none.
std::vector<DihedralSite> seam_vertex_sites(const DogMesh& mesh);

class DihedralAngleTerm : public Term {
 public:
  const char* name() const override { return "angles"; }
  /// Adds an angle constraint with target theta (radians); returns its block index.
  int add(const DihedralSite& site, double theta);
  void set_target(int b, double theta);
  double target(int b) const { return theta_[b]; }
  double alpha(int b) const { return sites_[b].alpha; }
  int point(int b) const { return sites_[b].point; }
  /// The dihedral angle the block's vertices p make (radians, in (-pi, pi]): the angle of
  /// (c - cos^2 alpha, s) above.
  double measure(int b, const Eigen::Vector3d* p) const;
  void clear();

  template <class T>
  void residual(int b, const T* const* p, T* r) const {
    using std::sqrt;
    const Block& k = blocks_[b];
    T eA[3], eB[3], t1[3], t2[3];
    for (int c = 0; c < 3; ++c) {
      eA[c] = p[k.slot[0]][c] - p[k.slot[1]][c];
      eB[c] = p[k.slot[2]][c] - p[k.slot[3]][c];
      const T P = k.t[0] * p[k.slot[0]][c] + (1 - k.t[0]) * p[k.slot[1]][c];
      const T Pb = k.t[1] * p[k.slot[4]][c] + (1 - k.t[1]) * p[k.slot[5]][c];
      const T Pf = k.t[2] * p[k.slot[6]][c] + (1 - k.t[2]) * p[k.slot[7]][c];
      t1[c] = P - Pb;
      t2[c] = Pf - P;
    }
    auto norm = [](const T* u) { return sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]); };
    const T n1 = norm(t1), n2 = norm(t2), lA = norm(eA), lB = norm(eB);
    T v[3], w[3];
    for (int c = 0; c < 3; ++c) v[c] = t1[c] * n2 + t2[c] * n1;
    w[0] = eA[1] * eB[2] - eA[2] * eB[1];
    w[1] = eA[2] * eB[0] - eA[0] * eB[2];
    w[2] = eA[0] * eB[1] - eA[1] * eB[0];
    T dot = T(0), wt = T(0);
    for (int c = 0; c < 3; ++c) {
      dot += eA[c] * eB[c];
      wt += w[c] * v[c];
    }
    r[0] = dot / (lA * lB) - k.cos_target;
    r[1] = k.orientation * wt / (norm(v) * lA * lB) - k.sin_target;
  }

  void evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const override;

 private:
  struct Block {
    std::array<int, 8> slot;  ///< index in the block of each role of DihedralSite::vertices
    std::array<double, 3> t;
    double orientation;
    double cos_target, sin_target;  ///< cos^2 alpha + sin^2 alpha cos theta, sin^2 alpha sin theta
  };
  std::vector<Block> blocks_;
  std::vector<DihedralSite> sites_;
  std::vector<double> theta_;
};

}  // namespace sdog
