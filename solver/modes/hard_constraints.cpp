#include "solver/modes/hard_constraints.h"

#include <cmath>

namespace sdog {
namespace {

// A stitching block's three rows are the coordinates of the gap between the two copies. Scaled by
// 10 sqrt(3), the constraint tolerance on each row bounds a tenth of the gap's length, and the
// least-squares restoration steps favour closing gaps where DOG and stitching rows pull against
// each other (a crease passing close to a grid vertex): with the scale sqrt(3) the final
// projection can stall with gaps of 1e-6 there and the DOG rows far below their tolerance.
const double kStitchingScale = 10 * std::sqrt(3.0);

}  // namespace

HardConstraints::HardConstraints(const DogProblem& problem, Stitching stitching) : dog_(&problem.dog) {
  if (stitching == Stitching::kExact && problem.stitching.block_count() > 0)
    stacked_ = std::make_unique<StackedTerm>(
        std::vector<StackedTerm::Part>{{&problem.dog, 1.0}, {&problem.stitching, kStitchingScale}});
}

}  // namespace sdog
