#pragma once
// The ADMM modes of the thesis (Deng, Lai, Peng, Yin 2017, "Parallel multi-block ADMM with o(1/k)
// convergence"), done right. The problem is min sum_i f_i(x_i) s.t. sum_i A_i x_i = 0 with f_i the
// objective restricted to patch i (bending, isometry, positions, edge points: no stitching) and
// A_i x_i the stitching rows (stitch_constraints.h: 3 rows per pair, 2 patches per row, N = 2).
// The DOG constraints stay hard inside every patch step (patch_sqp.h). One ADMM round: every
// patch takes one SQP step on its augmented objective, all in parallel (TBB), then the
// multipliers are updated; an iteration is `inner` rounds.
//
// vsadmm (variable splitting, Deng's Algorithm 1): per row, z_i and lambda_i for each side i;
//   patch i: f_i(x_i) + rho/2 |A_i x_i - z_i - lambda_i/rho|^2
//   z_i    <- A_i x_i - lambda_i/rho - (1/N)(sum_j A_j x_j - sum_j lambda_j/rho)   (new x)
//   lambda_i <- lambda_i - rho (A_i x_i - z_i)
// (z minimises the augmented Lagrangian f - lambda^T (Ax - z) + rho/2 |Ax - z|^2 under
// sum_i z_i = 0; z^0 uses lambda = 0.)
// jadmm (Jacobian ADMM): one lambda per row;
//   patch i: f_i(x_i) + rho/2 |A_i x_i + sum_{j != i} A_j x_j^k - lambda/rho|^2
//   lambda <- lambda - gamma rho sum_i A_i x_i^{k+1}
// proxjadmm: jadmm plus rho/2 (x_i - x_i^k)^T P (x_i - x_i^k), P = p I.
// The augmented terms are soft linear targets on each own copy (weight rho/2: the objective of a
// term is weight x |r|^2); the proximal term one target per vertex at x^k (weight rho p / 2).
//
// The fold bias and dihedral angle constraints couple two patches: each patch keeps their blocks
// with the other patch's vertices frozen at the round's start (patch_term.h), a Jacobi splitting
// of those terms next to the ADMM splitting of the stitching rows.
#include <memory>
#include <vector>

#include "solver/modes/mode.h"
#include "solver/modes/mode_options.h"
#include "solver/patches/patch_stepper.h"
#include "solver/problem/dog_problem.h"
#include "solver/terms/stitch_constraints.h"

namespace sdog {

enum class AdmmVariant { kVariableSplitting, kJacobian, kProximalJacobian };

class AdmmMode : public Mode {
 public:
  /// The problem must outlive the mode; the scenario is installed into it.
  AdmmMode(DogProblem& problem, const Scenario& scenario, AdmmVariant variant,
           const AdmmOptions& options, const SqpOptions& sqp);
  ModeKind kind() const override;
  StepReport iterate(const IterationContext& ctx, Dofs& x) override;

  const StitchConstraints& constraints() const { return rows_; }
  /// Multipliers, 3 per row block: vsadmm 2 per pair (side a, side b), the others 1 per pair.
  const std::vector<Eigen::Vector3d>& multipliers() const { return lambda_; }

 private:
  void set_targets(const Dofs& x);
  void update_multipliers(const Dofs& x);
  Dofs frozen_;  // the state the round started from
  DogProblem& problem_;
  Scenario scenario_;
  AdmmVariant variant_;
  AdmmOptions options_;
  StitchConstraints rows_;
  LinearPointTerm augmented_{"admm_augmented"};  // block 2k + s: the own copy of side s of pair k
  LinearPointTerm proximal_{"admm_proximal"};    // proxjadmm: block v: vertex v
  std::vector<Eigen::Vector3d> lambda_, z_;
  bool started_ = false;
  std::vector<std::unique_ptr<PatchStepper>> patches_;
};

}  // namespace sdog
