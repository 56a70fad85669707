#pragma once
// The standard solver: sequential quadratic programming on a sum of weighted squared residual
// terms f(x) with the DOG constraints c(x) = 0 as hard constraints. Multipliers lambda belong to
// the Lagrangian L = f - lambda^T c and are kept across iterations.
//
// One call of iterate() is one solver iteration (one point of the thesis's plots):
//
// 1. Optimality steps, until the KKT error max(|grad f - J^T lambda|_inf, |c|_inf) is below
//    kkt_tolerance (the first error counts 1e4 times, as in the reference, so at least one step
//    runs) or max_steps were taken. Each step solves the KKT system with its constraint block
//    regularised by epsilon (the reference's remedy is a random nudge of flat vertices; this one
//    is deterministic),
//        [ H  J^T     ] [ d               ]   [ -(grad f - J^T lambda) ]
//        [ J  -eps I  ] [ lambda - lambda+ ] = [ -c                     ],
//    through the symmetric positive definite K = H + rho J^T J + delta I (rho = 1/eps):
//        K d = -(grad f - J^T lambda) - rho J^T c,   lambda+ = lambda - rho (J d + c),
//    with CHOLMOD's supernodal Cholesky (symbolic analysis once, numeric factorisation per step,
//    K refilled in place). The step is damped by a backtracking line search with the Armijo
//    condition on the augmented Lagrangian Phi_mu = f - lambda^T c + mu/2 |c|^2, first with
//    mu = rho (d is a Newton direction for it), trying a second-order correction when the full
//    step is rejected. If that needs more than trusted_backtracks halvings, the step is bending a
//    nearly flat region, where the linearised constraints are degenerate and the full step
//    violates them quadratically: the search restarts with mu = merit_penalty, which accepts such
//    steps, and restoration removes the violation.
// 2. Restoration steps, until |c|_inf <= constraint_tolerance (final_constraint_tolerance when
//    polishing), at most max_restoration_steps: Gauss-Newton on rho/2 |c|^2 in the
//    metric of H, (H + rho J^T J) d = -rho J^T c, backtracking until |c| decreases. In order of
//    cost: a chord step with the last factorisation and its Jacobian (a second-order correction;
//    repeated while it cuts |c|_2^2 by 20%, at most 5 times), a local step on the neighbourhood of the violated rows
//    when they are few (local_restoration.h), a fresh global factorisation.
// 3. In the last iteration of a run only: a polishing iteration (up to polish_steps steps with the
//    constraints' curvature in H, then restoration to final_constraint_tolerance), kept only when
//    it ends more feasible than step 2 left the state; tried with rho capped at rho_max / 100, then
//    at rho_max. If the state is still above final_constraint_tolerance, project() finishes it.
//
// H is the objective's Hessian (exact for quadratic terms, clamped for isometry, Gauss-Newton
// for the others). The constraints' curvature -sum lambda_i Hess c_i (per-row multipliers) is
// available (lagrangian_hessian) but off by default: on flat regions the multipliers are not
// unique (the rows of J are dependent), their curvature is arbitrary, and with it the sheet locks
// (measured: 4_corners 21x21 ends at objective 2242 instead of 1.95).
// A non-PD K first raises rho, then the shift delta. Failure (NaN or infinity, a factorisation that
// fails at every shift, a line search that finds no decrease away from a stationary point) rolls
// the iteration back and is reported.
#include <Eigen/CholmodSupport>
#include <memory>
#include <string>
#include <vector>

#include "solver/sqp/block_matrix.h"
#include "solver/sqp/local_restoration.h"
#include "solver/sqp/sqp_options.h"
#include "solver/terms/term.h"
#include "solver/terms/weighted_term.h"

namespace sdog {

/// What one iteration did.
struct SqpReport {
  int steps = 0;              ///< optimality steps
  int restoration_steps = 0;  ///< steps that only restored the constraints (chord, local, global)
  int local_steps = 0;        ///< of which local
  int factorizations = 0;     ///< global numeric factorisations
  double constraint_max = 0;  ///< |c|_inf at the end
  double step_length = 0;     ///< line-search step of the last optimality step
  double factor_ms = 0;       ///< numeric factorisations and triangular solves
  double assembly_ms = 0;
  bool failed = false;
  std::string failure;        ///< why, when failed (x and the multipliers were rolled back)
};

class SqpSolver {
 public:
  /// `objective` terms and the hard `constraints` (a term whose residuals are the constraint
  /// values) over `vertex_count` vertices. Builds the sparse patterns and CHOLMOD's symbolic
  /// analysis once.
  SqpSolver(int vertex_count, std::vector<WeightedTerm> objective, const Term& constraints,
            const SqpOptions& options);
  ~SqpSolver();

  /// One iteration from x (updated in place; rolled back on failure). `last`: the last iteration
  /// of a run (tighter constraint tolerance).
  SqpReport iterate(Dofs& x, bool last = false);

  /// Only restoration steps (no objective step): moves x onto the constraints until |c| is within
  /// the constraint tolerance or max_restoration_steps are taken. For a state this solver did not
  /// compute (a mode switch), whose constraint residual may be far above the tolerance.
  SqpReport restore_constraints(Dofs& x);

  /// The projection onto the constraints that ends a run: chord and global restoration steps in
  /// the polishing metric (polish_epsilon) until |c|_inf <= final_constraint_tolerance, at most
  /// kProjectionSteps. Used by the patch modes' last iteration (final_projection.h) and by
  /// iterate() when its polish stops short of the final tolerance. Near flat regions the DOG
  /// constraints are degenerate (nearly quadratic in the normal motion) and these steps converge
  /// only linearly, hence the many steps (twolevel on 4_corners 81x81 needed 66, from 4.8e-5 to
  /// 4.2e-7, about 4 s once; with the restoration metric, restoration_epsilon 1e-6, it stalled at
  /// 1.7e-6, and 1e-7 gave 8.4e-7 after 200 steps). A projection that cannot reach the tolerance keeps its
  /// best state (reported in constraint_max); failed only for non-finite constraints.
  SqpReport project(Dofs& x);
  static constexpr int kProjectionSteps = 100;

  void set_weight(size_t term, double weight);
  double weight(size_t term) const { return objective_[term].weight; }
  const Eigen::VectorXd& multipliers() const { return lambda_; }
  void set_multipliers(const Eigen::VectorXd& lambda) { lambda_ = lambda; }
  const SqpOptions& options() const { return options_; }

  /// Weighted objective f(x) and its unweighted per-term parts (same order as the terms).
  double objective(const Dofs& x, std::vector<double>* unweighted = nullptr) const;
  /// Constraint values c(x) (row order of the constraint term's blocks).
  Eigen::VectorXd constraint_values(const Dofs& x) const;

  /// The quantities one step is built from (exposed for tests): weighted objective f, its
  /// gradient g, constraint values c and Jacobian J, and, if asked, the matrix
  /// K = H + rho J^T J (lower triangle; H as described above).
  struct Linearization {
    double f = 0;
    Eigen::VectorXd g, c;
    Eigen::SparseMatrix<double, Eigen::RowMajor> J;
  };
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  Linearization linearization(const Dofs& x, double rho = 0, Eigen::SparseMatrix<double>* K = nullptr);

 private:
  void linearize(const Dofs& x, Linearization& lin, bool hessian);
  /// Constraint values and Jacobian (in the fixed pattern); with `hessian` also J^T J into G_ and,
  /// when asked for, the constraints' curvature into H_.
  void fill_constraints(const Dofs& x, Eigen::VectorXd& c, RowMatrix& J, bool hessian);
  /// Linearises at x with the Hessian and factorises K; false if that fails.
  bool refactorize(const Dofs& x, Linearization& lin, double epsilon, SqpReport& report);
  void refresh_constant_hessian();
  double augmented_lagrangian(const Dofs& x, double mu) const;
  double kkt_error(const Linearization& lin) const;
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs, SqpReport& report) const;
  /// Restoration phase; false (with report.failure set) on NaN. `local_steps`: local steps allowed.
  bool restore(Dofs& x, Eigen::VectorXd& c, double tolerance, int max_steps, bool local_steps, SqpReport& report);

  int n_;
  std::vector<WeightedTerm> objective_;
  const Term& constraints_;
  SqpOptions options_;
  int rows_ = 0;
  std::vector<int> first_row_;
  Eigen::VectorXd lambda_;
  SymmetricBlockMatrix constant_hessian_;  // linear terms: recomputed when a weight changes
  bool constant_dirty_ = true;
  SymmetricBlockMatrix H_;  // objective Hessian of the last factorisation
  SymmetricBlockMatrix G_;  // J^T J of the same
  SymmetricBlockMatrix K_;  // H + rho G, handed to CHOLMOD
  std::unique_ptr<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower>> llt_;
  bool factored_ = false;
  double rho_ = 0;    // as factorised (raised above 1/epsilon if K was not PD)
  double delta_ = 0;  // shift of the last factorisation
  RowMatrix factored_J_;                     // constraint Jacobian where factorised
  RowMatrix J_pattern_;                      // constraint Jacobian pattern
  std::vector<std::vector<int>> column_rank_;  // per block vertex: its rank in the block's row
  LocalRestoration local_;
  bool polishing_ = false;  // polishing iteration: Lagrangian Hessian on
  double rho_cap_ = 0;      // rho may grow to this (options_.rho_max except when polishing)
  // One iteration; `last`: a polishing iteration (see iterate()).
  SqpReport solve_iteration(Dofs& x, bool last);
};

}  // namespace sdog
