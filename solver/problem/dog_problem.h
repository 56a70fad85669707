#pragma once
// The terms of a deformation problem on one DOG mesh, with the thesis's default weights:
// bending 1, isometry 20000/|E| (|E| = all quad edges, duplicates included), stitching 10,
// positions 25, edge points 25, angles 100 (the thesis: 1000, weights.h), fold bias 1, link 0
// (used by the coarse modes).
#include <string>
#include <vector>

#include "geometry/mesh/dog_mesh.h"
#include "geometry/mesh/quad_topology.h"
#include "solver/problem/weights.h"
#include "solver/terms/bending.h"
#include "solver/terms/crease_geometry.h"
#include "solver/terms/dihedral_angles.h"
#include "solver/terms/dog_constraints.h"
#include "solver/terms/fold_angles.h"
#include "solver/terms/fold_bias.h"
#include "solver/terms/isometry.h"
#include "solver/terms/linear_point_term.h"
#include "solver/terms/weighted_term.h"

namespace sdog {

/// Index of each objective term in DogProblem::objective_terms() (the run log's column order).
enum TermIndex : int {
  kBending = 0,
  kIsometry,
  kPositions,
  kEdgePoints,
  kStitching,
  kAngles,
  kFoldBias,
  kLink,
  kTermCount
};
const char* term_name(int index);

class DogProblem {
 public:
  DogProblem(const DogMesh& mesh, const QuadTopology& topology, const Weights& weights = {},
             double fold_sharpness = kFoldSharpness);
  DogProblem(const DogProblem&) = delete;
  DogProblem& operator=(const DogProblem&) = delete;

  const DogMesh& mesh() const { return mesh_; }
  const QuadTopology& topology() const { return topology_; }
  const Dofs& rest() const { return rest_; }

  /// The objective terms (in TermIndex order) with their effective weights.
  std::vector<WeightedTerm> objective_terms() const;
  /// The objective terms whose blocks join two patches and that a patch problem keeps with the
  /// other patch frozen (patch_term.h): fold bias and dihedral angles. (Stitching, the other one,
  /// becomes per-patch targets instead.)
  std::vector<const Term*> cross_patch_terms() const { return {&fold_bias, &angles}; }
  double effective_weight(int index) const;
  /// Sets free_sites (and the fold bias's blocks) from the angle blocks; before any solver is made
  /// for the problem (it fixes the sparsity pattern).
  void update_free_sites();

  Weights weights;
  LinearPointTerm bending{"bending"};
  IsometryTerm isometry;
  LinearPointTerm positions{"positions"}, edge_points{"edge_points"}, stitching{"stitching"},
      link{"link"};
  DihedralAngleTerm angles;
  std::vector<FoldSite> sites;  ///< every fold site of the mesh
  /// The fold sites without an angle block: the only ones the fold bias pushes and the fold test
  /// (check_folded) checks. A site with a signed angle target gets its direction from that.
  std::vector<FoldSite> free_sites;
  FoldBiasTerm fold_bias;  ///< over free_sites
  FoldAngles fold_angles;  ///< what the angle term's sites measure (diagnostics)
  DogConstraints dog;
  /// Per isometry block: whether its edge is paper: both ends lie in their patch's part of the
  /// sheet and no crease crosses it (the parts of cells beyond a crease only carry the patch's
  /// surface on).
  std::vector<char> sheet_edges;

 private:
  const DogMesh& mesh_;
  const QuadTopology& topology_;
  Dofs rest_;
  double fold_sharpness_;
};

}  // namespace sdog
