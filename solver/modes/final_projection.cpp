#include "solver/modes/final_projection.h"

#include "solver/sqp/sqp_solver.h"

namespace sdog {

FinalProjection::FinalProjection(const DogProblem& problem, const SqpOptions& sqp)
    : problem_(problem), options_(sqp) {}

FinalProjection::~FinalProjection() = default;

bool FinalProjection::project(Dofs& x, StepReport& report) {
  if (!solver_)
    solver_ = std::make_unique<SqpSolver>(problem_.mesh().vertex_count(),
                                          problem_.objective_terms(), problem_.dog, options_);
  return add_projection(solver_->project(x), report);
}

bool add_projection(const SqpReport& projection, StepReport& report) {
  report.work += projection.work;
  if (!projection.failed) return true;
  report.failed = true;
  report.failure = "final projection onto the DOG constraints: " + projection.failure;
  return false;
}

}  // namespace sdog
