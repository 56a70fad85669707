#include "solver/subsolvers_mode.h"

#include "geometry/errors.h"
#include "solver/crease_geometry.h"
#include "solver/patch_colouring.h"
#include "solver/patch_round.h"

namespace sdog {

std::string SubsolverOptions::validate() const {
  if (backend != "sqp" && backend != "ceres") return "backend must be \"sqp\" or \"ceres\", got \"" + backend + "\"";
  if (sweep != "jacobi" && sweep != "colours")
    return "sweep must be \"jacobi\" or \"colours\", got \"" + sweep + "\"";
  return patch.validate();
}

SubsolversMode::SubsolversMode(DogProblem& problem, const Scenario& scenario, const SubsolverOptions& options,
                               const SqpOptions& sqp)
    : problem_(problem), scenario_(scenario), options_(options) {
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
  terms.push_back({&targets_, problem_.weights.stitching, false});
  const PatchCoupling coupling{&frozen_, problem_.cross_patch_terms()};
  for (int p = 0; p < mesh.patch_count(); ++p) {
    if (options_.backend == "ceres")
      patches_.push_back(std::make_unique<PatchSolver>(mesh, p, terms, problem_.dog, options_.patch, coupling));
    else
      patches_.push_back(std::make_unique<PatchSqp>(mesh, p, terms, problem_.dog, sqp, coupling));
  }
  if (options_.sweep == "colours") {
    const std::vector<int> colour = colour_patches(mesh);
    for (int p = 0; p < mesh.patch_count(); ++p) {
      if (colour[p] >= static_cast<int>(sweeps_.size())) sweeps_.resize(colour[p] + 1, std::vector<char>(colour.size(), 0));
      sweeps_[colour[p]][p] = 1;
    }
  }
}

void SubsolversMode::set_time(double t) { scenario_.apply(problem_, t); }

void SubsolversMode::refresh_targets(const Dofs& x) {
  const Eigen::MatrixX3d X = to_positions(x);
  for (int b = 0; b < targets_.block_count(); ++b) targets_.set_target(b, DogMesh::position(X, other_[b]));
}

StepReport SubsolversMode::iterate(Dofs& x, bool last) {
  StepReport report;
  const Dofs x0 = x;
  const size_t rounds = sweeps_.empty() ? 1 : sweeps_.size();
  for (size_t r = 0; r < rounds; ++r) {
    refresh_targets(x);
    frozen_ = x;
    if (!step_patch_round(patches_, x, last, report, sweeps_.empty() ? nullptr : &sweeps_[r])) {
      x = x0;
      return report;
    }
  }
  report.step_length = 1;
  report.folded = check_folded(problem_.mesh(), problem_.sites, x).folded;
  return report;
}

}  // namespace sdog
