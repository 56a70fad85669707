#include "solver/final_projection.h"

namespace sdog {

namespace {
// Restoration steps of the projection. Near flat regions the DOG constraints are degenerate and
// Gauss-Newton on |c|^2 converges only linearly: 4_corners 81x81 (twolevel) needed 66 steps from
// 4.8e-5 to 4.2e-7, about 4 s once at the end of a run; the standard's 2 x 20 stopped at 2e-5.
constexpr int kProjectionSteps = 100;
}  // namespace

FinalProjection::FinalProjection(const DogProblem& problem, const SqpOptions& sqp) : problem_(problem), options_(sqp) {
  options_.constraint_tolerance = sqp.final_constraint_tolerance;
  options_.max_restoration_steps = kProjectionSteps;
  // As in the standard's polish: a weak metric term, which barely resists the last, small
  // corrections (with restoration_epsilon, 1e-6, the 4_corners 81x81 projection ended at 1.7e-6;
  // with 1e-7 at 8.4e-7 after 200 steps).
  options_.restoration_epsilon = sqp.polish_epsilon;
}

FinalProjection::~FinalProjection() = default;

bool FinalProjection::project(Dofs& x, StepReport& report) {
  if (!solver_)
    solver_ = std::make_unique<SqpSolver>(problem_.mesh().vertex_count(), problem_.objective_terms(), problem_.dog,
                                          options_);
  const Dofs x0 = x;
  const SqpReport r = solver_->restore_constraints(x);
  report.restoration_steps += r.restoration_steps;
  report.factorizations += r.factorizations;
  report.factor_ms += r.factor_ms;
  if (r.failed) {
    x = x0;
    report.failed = true;
    report.failure = "final projection onto the DOG constraints: " + r.failure;
    return false;
  }
  return true;
}

}  // namespace sdog
