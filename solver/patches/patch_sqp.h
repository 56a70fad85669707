#pragma once
// A patch stepped by the standard solver's SQP iteration (sqp_solver.h) on the patch's own
// residual blocks (patch_term.h: the same definitions, restricted and re-indexed): its own
// CHOLMOD factorisation, multipliers, line search and restoration to the same tolerances as the
// standard solver. Measured against the Ceres patch problem (patch_solver.h) in the README.
#include <memory>

#include "geometry/mesh/dog_mesh.h"
#include "solver/patches/patch_stepper.h"
#include "solver/patches/patch_term.h"
#include "solver/sqp/sqp_solver.h"

namespace sdog {

class PatchSqp : public PatchStepper {
 public:
  /// The terms, `dog` and the coupling's frozen state must outlive the stepper; their targets may
  /// change between steps.
  PatchSqp(const DogMesh& mesh, int patch, const std::vector<WeightedTerm>& terms, const Term& dog,
           const SqpOptions& options, const PatchCoupling& coupling = {});
  int patch() const override { return patch_; }
  int vertex_count() const override { return end_ - begin_; }
  PatchReport step(Dofs& x, bool last) override;
  void set_weight(size_t index, double weight) override { sqp_->set_weight(index, weight); }

 private:
  int patch_, begin_, end_;
  std::vector<std::unique_ptr<PatchTerm>> terms_;
  std::unique_ptr<PatchTerm> dog_;
  std::unique_ptr<SqpSolver> sqp_;
};

}  // namespace sdog
