#include "solver/modes/subsolvers_mode.h"

#include <algorithm>
#include <cmath>

#include "base/errors.h"
#include "solver/modes/patch_round.h"
#include "solver/patches/ceres/ceres_patch.h"
#include "solver/patches/patch_colouring.h"
#include "solver/patches/patch_sqp.h"
#include "solver/terms/crease_geometry.h"

namespace sdog {

SubsolversMode::SubsolversMode(DogProblem& problem, const Scenario& scenario,
                               const SubsolverOptions& options, const SqpOptions& sqp)
    : problem_(problem), scenario_(scenario), options_(options), projection_(problem, sqp) {
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
  PatchCoupling coupling{&frozen_, problem_.cross_patch_terms()};
  if (options_.fold_sharpness > 0 && options_.fold_sharpness != problem_.fold_bias.sharpness()) {
    fold_bias_ = std::make_unique<FoldBiasTerm>(mesh, problem_.free_sites, options_.fold_sharpness);
    terms[kFoldBias].term = fold_bias_.get();
    std::replace(coupling.split.begin(), coupling.split.end(),
                 static_cast<const Term*>(&problem_.fold_bias),
                 static_cast<const Term*>(fold_bias_.get()));
  }
  for (int p = 0; p < mesh.patch_count(); ++p) {
    if (options_.backend == PatchBackend::kCeres)
      patches_.push_back(make_ceres_patch(mesh, p, terms, problem_.dog, options_.patch, coupling));
    else
      patches_.push_back(std::make_unique<PatchSqp>(mesh, p, terms, problem_.dog, sqp, coupling));
  }
  // Jacobi: one round of every patch (every patch has colour 0).
  const int n = mesh.patch_count();
  const std::vector<int> colour =
      options_.sweep == PatchSweep::kColours ? colour_patches(mesh) : std::vector<int>(n, 0);
  sweeps_.assign(*std::max_element(colour.begin(), colour.end()) + 1, std::vector<char>(n, 0));
  for (int p = 0; p < n; ++p) sweeps_[colour[p]][p] = 1;
}

void SubsolversMode::set_time(double t) {
  scenario_.apply(problem_, t);
}

void SubsolversMode::refresh_targets(const Dofs& x) {
  const Eigen::MatrixX3d X = to_positions(x);
  for (int b = 0; b < targets_.block_count(); ++b)
    targets_.set_target(b, DogMesh::position(X, other_[b]));
}

StepReport SubsolversMode::iterate(const IterationContext& ctx, Dofs& x) {
  set_time(ctx.t);
  return round(x, ctx.last());
}

StepReport SubsolversMode::round(Dofs& x, bool last) {
  StepReport report;
  const Dofs x0 = x;
  for (const std::vector<char>& active : sweeps_) {
    refresh_targets(x);
    frozen_ = x;
    if (!step_patch_round(patches_, x, false, report, &active)) {
      x = x0;
      return report;
    }
  }
  if (last && !projection_.project(x, report)) {
    x = x0;
    return report;
  }
  report.step_length = 1;
  report.folded = check_folded(problem_.mesh(), problem_.free_sites, x).folded;
  return report;
}

}  // namespace sdog
