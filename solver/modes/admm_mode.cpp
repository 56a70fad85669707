#include "solver/modes/admm_mode.h"

#include <cmath>

#include "base/errors.h"
#include "solver/modes/patch_round.h"
#include "solver/patches/patch_sqp.h"
#include "solver/terms/crease_geometry.h"

namespace sdog {

AdmmMode::AdmmMode(DogProblem& problem, const Scenario& scenario, AdmmVariant variant,
                   const AdmmOptions& options, const SqpOptions& sqp)
    : problem_(problem),
      scenario_(scenario),
      variant_(variant),
      options_(options),
      rows_(problem.mesh()) {
  if (const std::string m = options_.validate(); !m.empty()) throw UsageError("admm options: " + m);
  scenario_.install(problem_);
  const DogMesh& mesh = problem_.mesh();
  for (int k = 0; k < rows_.pair_count(); ++k)
    for (int s = 0; s < 2; ++s) {
      const EdgePoint& e = rows_.side(k, s).copy;
      augmented_.add({{e.v1, e.t}, {e.v2, 1 - e.t}});
    }
  const bool vs = variant_ == AdmmVariant::kVariableSplitting;
  lambda_.assign(vs ? 2 * rows_.pair_count() : rows_.pair_count(), Eigen::Vector3d::Zero());
  if (vs) z_.assign(2 * rows_.pair_count(), Eigen::Vector3d::Zero());
  std::vector<WeightedTerm> terms =
      problem_.objective_terms();  // stitching blocks span two patches: dropped
  terms.push_back({&augmented_, 0.5 * options_.rho, false});
  if (variant_ == AdmmVariant::kProximalJacobian) {
    for (int v = 0; v < mesh.vertex_count(); ++v) proximal_.add({{v, 1.0}});
    terms.push_back(
        {&proximal_, 0.5 * options_.rho * options_.proximal_weight(mesh.patch_count()), false});
  }
  for (int p = 0; p < mesh.patch_count(); ++p)
    patches_.push_back(std::make_unique<PatchSqp>(
        mesh, p, terms, problem_.dog, sqp, PatchCoupling{&frozen_, problem_.cross_patch_terms()}));
}

ModeKind AdmmMode::kind() const {
  switch (variant_) {
    case AdmmVariant::kVariableSplitting:
      return ModeKind::kVsAdmm;
    case AdmmVariant::kJacobian:
      return ModeKind::kJAdmm;
    case AdmmVariant::kProximalJacobian:
      break;
  }
  return ModeKind::kProxJAdmm;
}

// The augmented term of side s is rho/2 |sign_s copy_s(x) - w|^2 = rho/2 |copy_s(x) - sign_s w|^2
// (sign_s = +-1): a target sign_s w on the unsigned copy.
void AdmmMode::set_targets(const Dofs& x) {
  const double rho = options_.rho;
  for (int k = 0; k < rows_.pair_count(); ++k)
    for (int s = 0; s < 2; ++s) {
      const double sign = rows_.side(k, s).sign;
      Eigen::Vector3d w;
      if (variant_ == AdmmVariant::kVariableSplitting) {
        if (!started_) z_[2 * k + s] = rows_.contribution(k, s, x) - 0.5 * rows_.residual(k, x);
        w = z_[2 * k + s] + lambda_[2 * k + s] / rho;
      } else {
        w = lambda_[k] / rho - rows_.contribution(k, 1 - s, x);
      }
      augmented_.set_target(2 * k + s, sign * w);
    }
  started_ = true;
  if (variant_ == AdmmVariant::kProximalJacobian)
    for (int v = 0; v < proximal_.block_count(); ++v) proximal_.set_target(v, vertex_of(x, v));
}

void AdmmMode::update_multipliers(const Dofs& x) {
  const double rho = options_.rho;
  for (int k = 0; k < rows_.pair_count(); ++k) {
    const Eigen::Vector3d g = rows_.residual(k, x);
    if (variant_ != AdmmVariant::kVariableSplitting) {
      lambda_[k] -= options_.gamma * rho * g;
      continue;
    }
    const Eigen::Vector3d mean =
        0.5 * (g - (lambda_[2 * k] + lambda_[2 * k + 1]) / rho);  // N = 2 patches per row
    for (int s = 0; s < 2; ++s) {
      const Eigen::Vector3d u = rows_.contribution(k, s, x);
      Eigen::Vector3d& z = z_[2 * k + s];
      Eigen::Vector3d& lambda = lambda_[2 * k + s];
      z = u - lambda / rho - mean;
      lambda -= rho * (u - z);
    }
  }
}

StepReport AdmmMode::iterate(const IterationContext& ctx, Dofs& x) {
  scenario_.apply(problem_, ctx.t);
  const bool last = ctx.last();
  StepReport report;
  const Dofs x0 = x;
  const auto lambda0 = lambda_, z0 = z_;
  const bool started0 = started_;
  for (int round = 0; round < options_.inner; ++round) {
    set_targets(x);
    frozen_ = x;
    if (!step_patch_round(patches_, x, last && round + 1 == options_.inner, report)) {
      x = x0;
      lambda_ = lambda0;
      z_ = z0;
      started_ = started0;
      return report;
    }
    update_multipliers(x);
  }
  report.step_length = 1;
  report.folded = check_folded(problem_.mesh(), problem_.free_sites, x).folded;
  return report;
}

}  // namespace sdog
