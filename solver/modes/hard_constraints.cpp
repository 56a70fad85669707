#include "solver/modes/hard_constraints.h"

#include <cmath>

namespace sdog {
namespace {

// A stitching block's three rows are the coordinates of the gap between the two copies; scaled by
// sqrt(3), the constraint tolerance on each row bounds the gap's length.
const double kStitchingScale = std::sqrt(3.0);

}  // namespace

HardConstraints::HardConstraints(const DogProblem& problem, Stitching stitching) : dog_(&problem.dog) {
  if (stitching == Stitching::kExact && problem.stitching.block_count() > 0)
    stacked_ = std::make_unique<StackedTerm>(
        std::vector<StackedTerm::Part>{{&problem.dog, 1.0}, {&problem.stitching, kStitchingScale}});
}

}  // namespace sdog
