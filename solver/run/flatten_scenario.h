#pragma once
// The flattening test of the thesis (Fig. 4.1, the ADMM test): start from a folded sheet and let
// the solver minimise the objective with a single position constraint, so that a correct solver
// unfolds the creases and drives the sheet flat (bending -> 0, stitching gap -> 0).
//
// The start state is the end of the fold scenario (scenario.h) run by the standard solver: every
// fold site folds from flat to `degrees` in 40 iterations, then 10 held. The flatten scenario then
// holds the bottom-left grid corner (vertex a of the thesis protocol) at its folded position
// (only to stop the sheet drifting: a rigid motion costs nothing) and asks for nothing else. Its
// creases unfold, so the standard mode's folding mode is off.
#include "solver/modes/mode_options.h"
#include "solver/problem/dog_problem.h"
#include "solver/problem/scenario.h"

namespace sdog {

/// Throws UsageError when the mesh has no fold sites or `degrees` is 0, SolverError when folding
/// the start state fails.
Scenario flatten_scenario(const DogMesh& mesh, const Weights& weights,
                          const StandardOptions& options, double degrees, int iterations = 250,
                          int hold = 50);

}  // namespace sdog
