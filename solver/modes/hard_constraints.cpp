#include "solver/modes/hard_constraints.h"

#include <cmath>

namespace sdog {
namespace {

// A stitching block's three rows are the coordinates of the gap between the two copies. Scaled by
// sqrt(3), the constraint tolerance on each row bounds the gap's length. The last iteration's
// projection weights them ten times more: where a crease passes close to a grid vertex, DOG and
// stitching rows pull against each other, and with the scale sqrt(3) the least-squares
// restoration steps can stall there with gaps around 1e-6 and the DOG rows far below their
// tolerance. During the iterations that weight sends some drags into other folds (four_corner_arcs
// 21x21 with the target set at once: objective 4.56 against 3.12).
const double kStitchingScale = std::sqrt(3.0);
const double kFinalStitchingScale = 10 * kStitchingScale;

}  // namespace

HardConstraints::HardConstraints(const DogProblem& problem, Stitching stitching)
    : dog_(&problem.dog) {
  if (stitching == Stitching::kExact && problem.stitching.block_count() > 0)
    stacked_ = std::make_unique<StackedTerm>(
        std::vector<StackedTerm::Part>{{&problem.dog, 1.0}, {&problem.stitching, kStitchingScale}});
}

void HardConstraints::use_final_scale(bool final) {
  if (stacked_) stacked_->set_scale(1, final ? kFinalStitchingScale : kStitchingScale);
}

}  // namespace sdog
