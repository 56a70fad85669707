#pragma once
// The standard solver: sequential quadratic programming on a sum of weighted squared residual
// terms f(x) with the DOG constraints c(x) = 0 as hard constraints. Multipliers lambda belong to
// the Lagrangian L = f - lambda^T c and are kept across iterations.
//
// One call of iterate() is one solver iteration (one point of the thesis's plots), in phases:
// sqp_step.cpp (optimality steps and their line search), sqp_restoration.cpp (restoration and
// the projection), sqp_linearization.cpp (the quantities a step is built from):
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
//    repeated while it cuts |c|_2^2 by 20%, at most 5 times), a local step on the neighbourhood of
//    the violated rows when they are few (local_fraction; local_restoration.h), a fresh global
//    factorisation. The standard mode with exact stitching takes no local steps (local_fraction
//    automatic): its violated rows after a step lie all along the creases, where local steps cost
//    more than the global ones they replace.
// 3. In the last iteration of a run only: a polishing iteration (up to polish_steps steps with the
//    constraints' curvature in H, then restoration to final_constraint_tolerance), kept only when
//    it ends more feasible than step 2 left the state; tried with rho capped at rho_max / 100, then
//    at rho_max. If the state is still above final_constraint_tolerance, project() finishes it.
//    The polish and that projection make at most polish_factorizations factorisations together;
//    a projection on its own (the start of a converging run's last iteration, the patch modes'
//    last iteration) has the same budget.
//
// H is the objective's Hessian (exact for quadratic terms, clamped for isometry, Gauss-Newton
// for the others). The constraints' curvature -sum lambda_i Hess c_i (per-row multipliers) is
// available (lagrangian_hessian) but off by default: on flat regions the multipliers are not
// unique (the rows of J are dependent), their curvature is arbitrary, and with it the sheet locks
// (docs/design/rejected.md).
// A non-PD K first raises rho, then the shift delta. Failure (NaN or infinity, a factorisation that
// fails at every shift, a line search that finds no decrease away from a stationary point) rolls
// the iteration back; iterate() reports it, converge() retries the pass with a shorter step.
#include <Eigen/Sparse>
#include <memory>
#include <string>
#include <vector>

#include "solver/sqp/block_matrix.h"
#include "solver/sqp/local_restoration.h"
#include "solver/sqp/sqp_options.h"
#include "solver/sqp/work.h"
#include "solver/terms/term.h"
#include "solver/terms/weighted_term.h"

namespace sdog {

class CholmodFactor;

/// What one iteration did.
struct SqpReport {
  Work work;
  double constraint_max = 0;  ///< |c|_inf at the end
  double step_length = 0;     ///< line-search step of the last optimality step
  /// -grad f . d of the last optimality step d: the objective's decrease a full step would give to
  /// first order.
  double full_step_decrease = 0;
  /// converge() only: a full step would lower f by at most converged_decrease (or two steps in a
  /// row changed it by at most that), and x is feasible.
  bool converged = false;
  bool failed = false;
  std::string failure;  ///< why, when failed (x and the multipliers were rolled back)
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
  /// of a run (tighter constraint tolerance, polish).
  SqpReport iterate(Dofs& x, bool last = false);

  /// Steps from x, each an optimality step and its restoration, until a full step would lower the
  /// objective by at most converged_decrease (relative, first order), or two steps in a row changed
  /// it by at most that, with the constraints within constraint_tolerance; at most `max_steps`.
  /// Its line search turns to the fallback merit penalty after the full step. Reports whether x
  /// converged. A pass that fails (a factorisation that no rho or shift makes positive definite, a
  /// non-finite Hessian, a line search without decrease) is taken back and retried with half the
  /// step, down to kSmallestPassStep; then x stays at the last good pass, not converged, and the
  /// call does not fail: a failed factorisation shortens the step, it does not end a run.
  SqpReport converge(Dofs& x, int max_steps);
  static constexpr double kSmallestPassStep = 1.0 / 64;

  /// Test seam: the next `count` factorisation attempts (every rho and shift tried counts) fail
  /// as if K were not positive definite.
  void inject_factorization_failures(int count) { injected_failures_ = count; }

  /// The last iteration's polish of x (above), its work added to `report`, whose constraint_max
  /// is x's on entry and is updated. At most polish_factorizations factorisations (0: no limit).
  void polish(Dofs& x, SqpReport& report);

  /// Only restoration steps (no objective step): moves x onto the constraints until |c| is within
  /// the constraint tolerance or max_restoration_steps are taken. For a state this solver did not
  /// compute (a mode switch), whose constraint residual may be far above the tolerance.
  SqpReport restore_constraints(Dofs& x);

  /// The projection onto the constraints that ends a run: chord and global restoration steps in
  /// the polishing metric (polish_epsilon) until |c|_inf <= final_constraint_tolerance, at most
  /// projection_steps, then as many more with local steps if that stops short. Used by the patch
  /// modes' last iteration (final_projection.h) and by iterate() when its polish stops short of
  /// the final tolerance. Near flat regions the DOG constraints are nearly quadratic in the normal
  /// motion and these steps converge only linearly, hence the many steps. A projection that cannot
  /// reach the tolerance keeps its best state (reported in constraint_max); failed only for
  /// non-finite constraints. At most polish_factorizations factorisations (0: no limit), shared
  /// with the polish when the polish calls it.
  SqpReport project(Dofs& x);

  /// The ordinary steps' restoration stops within max(tolerance, constraint_tolerance) (0, the
  /// default: constraint_tolerance). The standard mode loosens it between continuation sub-steps.
  void set_restoration_tolerance(double tolerance) { restoration_tolerance_ = tolerance; }
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
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  struct Linearization {
    double f = 0;
    Eigen::VectorXd g, c;
    RowMatrix J;
  };
  Linearization linearization(const Dofs& x, double rho = 0,
                              Eigen::SparseMatrix<double>* K = nullptr);

 private:
  /// How the optimality steps and the restoration of one pass are made: an ordinary iteration or
  /// the last iteration's polish.
  struct Pass {
    double tolerance;  ///< |c|_inf the restoration aims for
    int max_steps;     ///< optimality steps
    int max_restoration_steps;
    bool stop_when_feasible;     ///< optimality steps end once |c|_inf <= tolerance
    bool curvature;              ///< the constraints' curvature -sum lambda_i Hess c_i in H
    double restoration_epsilon;  ///< metric of the restoration steps
    double rho_cap;              ///< rho may grow to this to make K positive definite
    bool first_step_always;      ///< the first KKT error counts 1e4 times (iterate())
    int trusted_backtracks;      ///< halvings with mu = rho before the fallback merit penalty
    double max_step = 1;         ///< the line search starts with this fraction of the step
  };
  Pass ordinary_pass() const;
  Pass polish_pass(double rho_cap) const;
  /// Restoration settings: how far, how many steps, when local steps are taken, the metric.
  struct Restoration {
    double tolerance;
    int max_steps;
    double local_fraction;  ///< local steps while at most this share of rows is violated (0: none)
    double epsilon;
    double rho_cap;
  };
  /// Result of one optimality step.
  enum class StepOutcome { kTaken, kStationary, kFailed };

  // sqp_solver.cpp: the iteration and its polish.
  SqpReport run_pass(Dofs& x, const Pass& pass);
  /// After a pass of converge(): the restoration's epsilon of the next pass, from how the pass's
  /// restoration went.
  void adapt_restoration(Pass& pass, const SqpReport& r) const;
  /// False once the last iteration (polish and projection) has used its factorisations.
  bool within_budget() const { return factorizations_ < factorization_stop_; }
  /// The last iteration's factorisation budget (polish_factorizations, 0: none) from construction
  /// to destruction. A budget opened inside another (the projection that finishes a polish) shares
  /// the outer one.
  class LastIterationBudget {
   public:
    explicit LastIterationBudget(SqpSolver& solver);
    ~LastIterationBudget();
    LastIterationBudget(const LastIterationBudget&) = delete;
    LastIterationBudget& operator=(const LastIterationBudget&) = delete;

   private:
    SqpSolver& solver_;
    bool owner_;
  };
  // sqp_step.cpp: one optimality step (KKT solve and line search).
  StepOutcome optimality_step(Dofs& x, Linearization& lin, const Pass& pass, SqpReport& report);
  /// options_.local_fraction with the automatic value resolved.
  double local_fraction() const {
    return options_.local_fraction < 0 ? SqpOptions::kDefaultLocalFraction
                                       : options_.local_fraction;
  }
  /// A backtracking search along d with the Armijo condition on Phi_mu (see above).
  struct LineSearch {
    bool accepted = false;
    double alpha = 1;  ///< the step length taken
    double phi0 = 0;   ///< Phi_mu at x
    double slope = 0;  ///< its directional derivative along d
    Dofs x;            ///< the point accepted
  };
  LineSearch line_search(const Dofs& x, const Linearization& lin, const Eigen::VectorXd& d,
                         const Eigen::VectorXd& grad_phi, const Eigen::VectorXd& Jtc, double mu,
                         int max_halvings, double max_step, SqpReport& report) const;
  // sqp_restoration.cpp. False (with report.failure set) on NaN.
  bool restore(Dofs& x, Eigen::VectorXd& c, const Restoration& settings, SqpReport& report);
  // sqp_linearization.cpp.
  /// The objective's value and gradient and the constraints at x (no Hessian); false when any of
  /// them is not finite.
  bool relinearize(const Dofs& x, Linearization& lin, SqpReport& report);
  void linearize(const Dofs& x, Linearization& lin, bool hessian, bool curvature);
  /// Constraint values and Jacobian (in the fixed pattern); with `hessian` also J^T J into G and,
  /// with `curvature`, the constraints' curvature into H.
  void fill_constraints(const Dofs& x, Eigen::VectorXd& c, RowMatrix& J, bool hessian,
                        bool curvature);
  /// Linearises at x with the Hessian and factorises K; false if that fails.
  bool refactorize(const Dofs& x, Linearization& lin, double epsilon, bool curvature,
                   double rho_cap, SqpReport& report);
  void refresh_constant_hessian();
  double augmented_lagrangian(const Dofs& x, double mu) const;
  double kkt_error(const Linearization& lin) const;
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs, SqpReport& report) const;

  int n_;
  std::vector<WeightedTerm> objective_;
  const Term& constraints_;
  SqpOptions options_;
  /// Constraint rows: the first row of each block, the Jacobian's pattern (each row holds its
  /// block's vertices in increasing order) and each block vertex's rank in its row.
  struct Rows {
    int count = 0;
    std::vector<int> first;
    RowMatrix pattern;
    std::vector<std::vector<int>> column_rank;
  } rows_;
  Eigen::VectorXd lambda_;
  double restoration_tolerance_ = 0;
  /// The matrices of a factorisation: the linear terms' constant Hessian (recomputed when a
  /// weight changes), the objective Hessian H, J^T J (G) and K = H + rho G (handed to CHOLMOD).
  struct Matrices {
    SymmetricBlockMatrix constant, H, G, K;
    bool constant_dirty = true;
  } m_;
  /// The last factorisation: valid or not, its rho (raised above 1/epsilon if K was not PD), its
  /// shift and the constraint Jacobian it was made at (chord steps).
  std::unique_ptr<CholmodFactor> factor_;
  bool factored_ = false;
  double rho_ = 0;
  double delta_ = 0;
  RowMatrix factored_J_;
  LocalRestoration local_;
  long factorizations_ = 0;    ///< made so far
  int injected_failures_ = 0;  ///< inject_factorization_failures()
  long factorization_stop_;    ///< no factorisation from this count on (LastIterationBudget)
};

}  // namespace sdog
