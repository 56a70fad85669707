#include "solver/final_projection.h"

namespace sdog {

FinalProjection::FinalProjection(const DogProblem& problem, const SqpOptions& sqp) : problem_(problem), options_(sqp) {}

FinalProjection::~FinalProjection() = default;

bool FinalProjection::project(Dofs& x, StepReport& report) {
  if (!solver_)
    solver_ = std::make_unique<SqpSolver>(problem_.mesh().vertex_count(), problem_.objective_terms(), problem_.dog,
                                          options_);
  const SqpReport r = solver_->project(x);
  report.restoration_steps += r.restoration_steps;
  report.factorizations += r.factorizations;
  report.factor_ms += r.factor_ms;
  if (r.failed) {
    report.failed = true;
    report.failure = "final projection onto the DOG constraints: " + r.failure;
    return false;
  }
  return true;
}

}  // namespace sdog
