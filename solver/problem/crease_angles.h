#pragma once
// What a state's fold angles say about the angle targets: creases.csv (every fold site), the
// direction report of run.json and the run's summary.
#include <array>
#include <string>
#include <vector>

#include "solver/problem/scenario.h"
#include "solver/terms/fold_angles.h"

namespace sdog {

/// How one crease folds against its angle targets (those of problem.angles).
struct CreaseFold {
  int curve = 0;
  int sites = 0;    ///< fold sites with an angle target
  int bent = 0;     ///< of them bent by more than kBentDegrees
  int against = 0;  ///< of the bent ones, bent against their target's sign
  int against_near_tip =
      0;  ///< of those, within kFoldTipRadius of a fold tip (geometry/pattern/fold_tips.h)
  double target = 0;        ///< median target angle (degrees)
  double angle = 0;         ///< median angle reached (degrees)
  double median_error = 0;  ///< median |angle - target| (degrees)
};
/// Every crease with at least one angle target, in crease order.
std::vector<CreaseFold> crease_folds(const DogProblem& problem, const Dofs& x);

/// creases.csv: one row per fold site with its crease curve, the crease's element id, assignment,
/// the scenario's target angle there (empty without one) and the signed angle reached in x.
std::string creases_csv(const DogMesh& mesh, const Scenario& scenario, const Dofs& x);

}  // namespace sdog
