#pragma once
// The hard constraints of the standard solver: the DOG constraints and, with exact stitching,
// the stitching of every crease point (its two copies coincide), stacked into one term.
#include <memory>

#include "solver/modes/mode_options.h"
#include "solver/problem/dog_problem.h"
#include "solver/terms/stacked_term.h"

namespace sdog {

class HardConstraints {
 public:
  /// The problem must outlive this.
  HardConstraints(const DogProblem& problem, Stitching stitching);
  const Term& term() const { return stacked_ ? *stacked_ : *dog_; }
  /// The stitching rows' scale of the last iteration's projection (true) or of the iterations.
  void use_final_scale(bool final);

 private:
  const Term* dog_;
  std::unique_ptr<StackedTerm> stacked_;
};

}  // namespace sdog
