#pragma once
// Several terms seen as one: the blocks of the first term, then those of the second, ..., each
// part's residuals multiplied by its scale. Used to hand the SQP solver one constraint term made of
// the DOG constraints and the stitching of the crease points (exact stitching, hard_constraints.h).
#include <vector>

#include "solver/terms/term.h"

namespace sdog {

class StackedTerm : public Term {
 public:
  struct Part {
    const Term* term;  ///< must outlive this one and keep its blocks
    double scale;
  };
  explicit StackedTerm(std::vector<Part> parts);
  /// Changes the scale of part `part` (its blocks stay).
  void set_scale(int part, double scale) { parts_[part].scale = scale; }
  const char* name() const override { return "constraints"; }

  void evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const override;
  bool is_linear() const override;
  bool has_second_order() const override;
  void add_second_order(int b, const Eigen::Vector3d* p, const double* y, double* H) const override;
  void curvature_weights(int b, const double* r, double* y) const override;

 private:
  /// The part block b belongs to and its index there.
  std::pair<const Part*, int> locate(int b) const;
  std::vector<Part> parts_;
  std::vector<int> first_;  ///< first stacked block of each part
};

}  // namespace sdog
