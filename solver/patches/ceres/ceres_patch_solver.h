#pragma once
// One patch of a DOG as its own nonlinear least-squares problem, solved with Ceres: every
// objective residual block whose vertices all lie in the patch (one Ceres parameter block per
// vertex) plus the patch's DOG constraints through an augmented-Lagrangian outer loop:
//
//   minimise f_P(x) + mu/2 |c(x) - lambda/mu|^2   (Ceres, Levenberg-Marquardt, sparse Cholesky)
//   lambda <- lambda - mu c(x)
//   mu <- growth * mu  when |c|_inf is above the tolerance and did not fall below a quarter of
//                      its previous value
//
// until |c|_inf <= constraint_tolerance (the standard solver's per-iteration tolerance by
// default). Multipliers and the penalty are kept across solves (warm start). The blocks are those
// of PatchTerm (patch_term.h): blocks of the coupling's split terms (fold bias, angles) that reach
// into other patches are kept with those vertices frozen; other cross-patch blocks (stitching) are
// not part of a patch problem: the multi-patch modes turn them into per-patch targets.
//
// Patch problems are independent; solve_patches() runs them in parallel with TBB (each solve is
// single threaded), and the result does not depend on the number of threads.
#include <ceres/ceres.h>

#include <memory>
#include <vector>

#include "geometry/mesh/dog_mesh.h"
#include "solver/patches/ceres/ceres_cost.h"
#include "solver/patches/ceres/ceres_patch_options.h"
#include "solver/patches/patch_stepper.h"
#include "solver/patches/patch_term.h"
#include "solver/terms/dog_constraints.h"
#include "solver/terms/weighted_term.h"

namespace sdog {

class CeresPatchSolver : public PatchStepper {
 public:
  /// Patch `patch` of `mesh`: the blocks of `terms` inside it (and the coupled ones) and the
  /// blocks of `dog` inside it. The terms, `dog` and the coupling's frozen state must outlive the
  /// solver; their targets may change between solves.
  CeresPatchSolver(const DogMesh& mesh, int patch, const std::vector<WeightedTerm>& terms,
                   const Term& dog, const CeresPatchOptions& options = {},
                   const PatchCoupling& coupling = {});
  CeresPatchSolver(const CeresPatchSolver&) = delete;
  CeresPatchSolver& operator=(const CeresPatchSolver&) = delete;

  int patch() const override { return patch_; }
  int vertex_count() const override { return end_ - begin_; }
  PatchReport step(Dofs& x, bool last) override;
  /// Solves from x and writes the patch's vertices back into x (others are not touched).
  PatchReport solve(Dofs& x);
  /// Changes the weight of terms[index] (as passed to the constructor).
  void set_weight(size_t index, double weight) override;

  /// Objective (weighted, without augmented terms) and |c|_inf of the patch at x.
  double objective(const Dofs& x) const;
  double dog_max(const Dofs& x) const;

 private:
  void load(const Dofs& x);
  double constraint_max_local();  // of local_
  int patch_, begin_, end_;
  CeresPatchOptions options_;
  std::vector<double> local_;  // the patch's coordinates, Ceres' parameter blocks
  std::unique_ptr<ceres::Problem> problem_;
  std::vector<std::unique_ptr<PatchTerm>> terms_;   // the objective terms restricted to the patch
  std::vector<std::vector<TermCost*>> term_costs_;  // per objective term, one per block
  std::vector<double> weights_;
  std::unique_ptr<PatchTerm> dog_;
  std::vector<TermCost*> dog_costs_;
  Eigen::VectorXd lambda_;  // per patch constraint row
  Eigen::VectorXd offset_;  // lambda / mu, the augmented terms' offsets
  double mu_;
};

}  // namespace sdog
