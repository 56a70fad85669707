#pragma once
// The last iteration of the patch modes (subsolvers, twolevel, coarse): after an ordinary patch
// round (constraints to the per-iteration tolerance), the whole fine state is moved onto the DOG
// constraints to the final tolerance by SqpSolver::project (the standard solver's restoration
// steps, Gauss-Newton on |c|^2 in the metric of the objective's Hessian: the smallest correction
// in that metric; the standard mode finishes a polish that stops short with the same projection).
//
// Why not a polishing patch round: the patches polish with their neighbours frozen and reach the
// final tolerance only through large exact-Hessian steps, which tip fine fold sites across their
// crease and undo the run's result (docs/design/rejected.md).
// The projection is the smallest move onto the constraints: about sqrt of the residual it removes
// near flat regions, where the constraints are nearly quadratic in the normal motion.
#include <memory>

#include "solver/modes/mode.h"
#include "solver/problem/dog_problem.h"
#include "solver/sqp/sqp_options.h"

namespace sdog {

class SqpSolver;
struct SqpReport;

class FinalProjection {
 public:
  /// The problem must outlive this; `sqp` gives the tolerances and restoration settings.
  FinalProjection(const DogProblem& problem, const SqpOptions& sqp);
  ~FinalProjection();
  /// Moves x onto the DOG constraints to sqp.final_constraint_tolerance (unchanged if it is
  /// already there) and adds the work to `report`. A projection that cannot reach the tolerance
  /// keeps its best state; the run's diagnostics show the residual left, as for the standard mode.
  /// False (x unchanged, report failed) only when the constraints are not finite.
  bool project(Dofs& x, StepReport& report);

 private:
  const DogProblem& problem_;
  SqpOptions options_;
  std::unique_ptr<SqpSolver> solver_;  // built at the first projection (symbolic analysis)
};

/// Adds a projection's work (SqpSolver::project) to `report`; a failed projection fails the report.
bool add_projection(const SqpReport& projection, StepReport& report);

}  // namespace sdog
