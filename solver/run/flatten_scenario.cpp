#include "solver/run/flatten_scenario.h"

#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/mesh/quad_topology.h"
#include "solver/modes/standard_mode.h"
#include "solver/run/run.h"

namespace sdog {

Scenario flatten_scenario(const DogMesh& mesh, const Weights& weights,
                          const StandardOptions& options, double degrees, int iterations,
                          int hold) {
  constexpr int kFoldIterations = 40, kFoldHold = 10;
  if (degrees == 0)
    throw UsageError(
        "the flatten scenario starts from a folded sheet: the fold angle must not be 0");
  const Scenario fold = fold_scenario(mesh, degrees, kFoldIterations, kFoldHold);
  if (fold.angles.empty())
    throw UsageError(
        "the flatten scenario starts from every crease folded, but the mesh has no fold sites "
        "(crease points strictly inside a grid edge between two patches): try another "
        "resolution");
  const QuadTopology topology = quad_topology(mesh);
  DogProblem problem(mesh, topology, weights);
  StandardMode mode(problem, fold, options);
  Dofs x = fold.start(mesh);
  const RunSummary folding = run_scenario(mode, problem, fold, x, {});
  if (folding.failed())
    throw SolverError("the flatten scenario's start state (every crease folded to " +
                      format_number(degrees) +
                      " degrees by the standard solver) failed: " + folding.failure);

  Scenario s;
  s.name = "flatten";
  s.iterations = iterations;
  s.hold = hold;
  s.initial = x;
  s.keeps_folds = false;
  const int a = corners_scenario(mesh).positions.front().vertex;
  s.positions.push_back({a, vertex_of(x, a), vertex_of(x, a)});
  return s;
}

}  // namespace sdog
