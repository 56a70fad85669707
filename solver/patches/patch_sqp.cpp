#include "solver/patches/patch_sqp.h"

#include "base/stopwatch.h"

namespace sdog {

PatchSqp::PatchSqp(const DogMesh& mesh, int patch, const std::vector<WeightedTerm>& terms,
                   const Term& dog, const SqpOptions& options, const PatchCoupling& coupling)
    : patch_(patch), begin_(mesh.patch_begin[patch]), end_(mesh.patch_begin[patch + 1]) {
  std::vector<WeightedTerm> local;
  for (const auto& t : terms) {
    terms_.push_back(
        std::make_unique<PatchTerm>(*t.term, begin_, end_, coupling.frozen_for(t.term)));
    local.push_back({terms_.back().get(), t.weight, t.exact_hessian});
  }
  dog_ = std::make_unique<PatchTerm>(dog, begin_, end_);
  sqp_ = std::make_unique<SqpSolver>(end_ - begin_, local, *dog_, options);
}

PatchReport PatchSqp::step(Dofs& x, bool last) {
  const auto t0 = Clock::now();
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(end_ - begin_);
  Dofs local = x.segment(3 * static_cast<Eigen::Index>(begin_), n);
  const SqpReport r = sqp_->iterate(local, last);
  x.segment(3 * static_cast<Eigen::Index>(begin_), n) =
      local;  // rolled back by the solver on failure
  PatchReport report;
  report.patch = patch_;
  // A patch row counts optimality steps, factorisations and their time (not restoration steps).
  report.work.steps = r.work.steps;
  report.work.factorizations = r.work.factorizations;
  report.work.factor_ms = r.work.factor_ms;
  report.dog_max = r.constraint_max;
  report.converged = !r.failed;
  report.objective = sqp_->objective(local);
  report.ms = ms_since(t0);
  return report;
}

}  // namespace sdog
