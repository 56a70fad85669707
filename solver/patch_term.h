#pragma once
// A term restricted to one patch: the blocks of a term whose vertices all lie in the patch's
// vertex range [begin, end), with vertex indices shifted by -begin. Evaluation is forwarded to the
// wrapped term, so a patch problem uses the very same residual definitions as the whole mesh.
#include "solver/term.h"

namespace sdog {

class PatchTerm : public Term {
 public:
  PatchTerm(const Term& term, int begin, int end);
  const char* name() const override { return term_.name(); }
  void evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const override {
    term_.evaluate(source_[b], p, r, J);
  }
  bool is_linear() const override { return term_.is_linear(); }
  void add_second_order(int b, const Eigen::Vector3d* p, const double* y, double* H) const override {
    term_.add_second_order(source_[b], p, y, H);
  }
  bool has_second_order() const override { return term_.has_second_order(); }
  void curvature_weights(int b, const double* r, double* y) const override {
    term_.curvature_weights(source_[b], r, y);
  }
  /// The wrapped term's index of block b.
  int source_block(int b) const { return source_[b]; }

 private:
  const Term& term_;
  std::vector<int> source_;
};

}  // namespace sdog
