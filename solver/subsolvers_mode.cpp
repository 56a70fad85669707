#include "solver/subsolvers_mode.h"

#include "geometry/errors.h"
#include "solver/crease_geometry.h"

namespace sdog {

std::string SubsolverOptions::validate() const {
  if (const std::string m = patch.validate(); !m.empty()) return m;
  if (!(final_constraint_tolerance > 0)) return "final_constraint_tolerance must be positive";
  return "";
}

SubsolversMode::SubsolversMode(DogProblem& problem, const Scenario& scenario, const SubsolverOptions& options)
    : problem_(problem), scenario_(scenario), options_(options) {
  if (!scenario.angles.empty())
    throw UsageError("mode subsolvers does not support dihedral angle constraints yet (scenario '" + scenario.name +
                     "' has " + std::to_string(scenario.angles.size()) + "); use --mode standard");
  scenario_.install(problem_);
  const DogMesh& mesh = problem_.mesh();
  for (const auto& pair : mesh.stitching.pairs) {
    const auto& point = mesh.stitching.points[pair.point];
    for (const auto& [own, other] : {std::pair{pair.a, pair.b}, std::pair{pair.b, pair.a}}) {
      const EdgePoint& e = point.copies[own];
      targets_.add({{e.v1, e.t}, {e.v2, 1 - e.t}});
      other_.push_back(point.copies[other]);
    }
  }
  std::vector<WeightedTerm> terms = problem_.objective_terms();
  terms.push_back({&targets_, 0.5 * problem_.weights.stitching, false});
  for (int p = 0; p < mesh.patch_count(); ++p)
    solvers_.push_back(std::make_unique<PatchSolver>(mesh, p, terms, problem_.dog, options_.patch));
}

void SubsolversMode::set_time(double t) { scenario_.apply(problem_, t); }

void SubsolversMode::refresh_targets(const Dofs& x) {
  const Eigen::MatrixX3d X = to_positions(x);
  for (int b = 0; b < targets_.block_count(); ++b) targets_.set_target(b, DogMesh::position(X, other_[b]));
}

StepReport SubsolversMode::iterate(Dofs& x, bool last) {
  StepReport report;
  const Dofs x0 = x;
  refresh_targets(x);
  const double tolerance = last ? options_.final_constraint_tolerance : options_.patch.constraint_tolerance;
  for (auto& s : solvers_) s->set_constraint_tolerance(tolerance);
  report.patches = solve_patches(solvers_, x);
  if (!x.allFinite()) {
    x = x0;
    report.failed = true;
    report.failure = "a patch solve produced NaN or infinity";
    return report;
  }
  for (const auto& p : report.patches) {
    report.sqp_steps += p.inner;
    report.factor_ms += p.linear_ms;
  }
  report.step_length = 1;
  report.folded = check_folded(problem_.mesh(), problem_.sites, x).folded;
  return report;
}

}  // namespace sdog
