#pragma once
// A term restricted to one patch: the blocks of a term whose vertices lie in the patch's vertex
// range [begin, end), with vertex indices shifted by -begin. Evaluation is forwarded to the wrapped
// term, so a patch problem uses the very same residual definitions as the whole mesh.
//
// With a `frozen` state, blocks that reach into other patches are kept too: their outside
// vertices are read from the frozen state (the other patches' previous iterate, block-Jacobi
// style) and only the inside vertices are unknowns. This splits cross-patch terms (fold bias,
// dihedral angles) into one-sided halves against the other patch's frozen edge.
#include <vector>

#include "solver/terms/term.h"

namespace sdog {

/// Cross-patch terms of a patch problem: the blocks of the `split` terms that reach into other
/// patches are kept with those vertices read from `frozen`.
struct PatchCoupling {
  const Dofs* frozen = nullptr;
  std::vector<const Term*> split;
  /// The frozen state for `term` if it is split, else nullptr.
  const Dofs* frozen_for(const Term* term) const;
};

class PatchTerm : public Term {
 public:
  /// `frozen` (if given) must outlive the term; the caller refreshes it between steps and must not
  /// change it while a step runs.
  PatchTerm(const Term& term, int begin, int end, const Dofs* frozen = nullptr);
  const char* name() const override { return term_.name(); }
  void evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const override;
  bool is_linear() const override { return term_.is_linear(); }
  void add_second_order(int b, const Eigen::Vector3d* p, const double* y, double* H) const override;
  bool has_second_order() const override { return term_.has_second_order(); }
  void curvature_weights(int b, const double* r, double* y) const override {
    term_.curvature_weights(source_[b], r, y);
  }
  /// The wrapped term's index of block b.
  int source_block(int b) const { return source_[b]; }
  /// Number of blocks with frozen outside vertices.
  int split_block_count() const { return split_count_; }

 private:
  bool is_split(int b) const {
    return inside_offsets_[b + 1] - inside_offsets_[b] != term_.block_size(source_[b]);
  }
  // The full vertex positions of split block b: inside ones from p, outside ones from the frozen
  // state.
  void gather_full(int b, const Eigen::Vector3d* p, Eigen::Vector3d* full) const;

  const Term& term_;
  const Dofs* frozen_;
  std::vector<int> source_;
  // For block b: the slots (positions in the source block) of its inside vertices,
  // inside_slots_[inside_offsets_[b] .. inside_offsets_[b+1]).
  std::vector<int> inside_offsets_{0}, inside_slots_;
  int split_count_ = 0;
};

}  // namespace sdog
