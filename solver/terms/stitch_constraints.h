#pragma once
// The stitching pairs as linear equality constraints between patches, sum_i A_i x_i = 0, for the
// ADMM modes (admm_mode.h): for pair k with copy a in patch i and copy b in patch j,
//   copy_a(x_i) - copy_b(x_j) = 0,   copy = t p_v1 + (1 - t) p_v2,
// three rows per pair (x, y and z each tied on its own; tying only their sum, one row with t on
// the x, y and z columns, is the reference implementation's bug). A_i x_i stacks patch i's signed
// copies: side 0 (copy a, sign +1) and side 1 (copy b, sign -1). Every row involves two patches.
#include <array>
#include <vector>

#include "geometry/mesh/dog_mesh.h"
#include "solver/terms/term.h"

namespace sdog {

class StitchConstraints {
 public:
  struct Side {
    EdgePoint copy;
    int patch;
    double sign;  ///< +1 for copy a, -1 for copy b
  };

  explicit StitchConstraints(const DogMesh& mesh);
  int pair_count() const { return static_cast<int>(sides_.size()); }
  const Side& side(int pair, int s) const { return sides_[pair][s]; }

  /// The side's contribution to the pair's three rows: sign * copy(x).
  Eigen::Vector3d contribution(int pair, int s, const Dofs& x) const;
  /// The pair's three rows, sum over both sides: copy_a(x) - copy_b(x).
  Eigen::Vector3d residual(int pair, const Dofs& x) const;
  /// All rows (3 per pair, pair by pair): sum_i A_i x_i.
  Eigen::VectorXd residuals(const Dofs& x) const;

 private:
  std::vector<std::array<Side, 2>> sides_;
};

}  // namespace sdog
