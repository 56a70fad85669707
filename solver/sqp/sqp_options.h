#pragma once
// The options of the SQP solver (sqp_solver.h says what each one does) and their table
// (base/option_table.h): key, bounds and help of every option.
#include <string>

#include "base/option_table.h"

namespace sdog {

struct SqpOptions {
  static constexpr double kDefaultLocalFraction = 0.1;
  double kkt_tolerance = 1e-3;  ///< on max(|grad f - J^T lambda|_inf, |c|_inf)
  int max_steps = 1;            ///< optimality steps per iteration (reference: 5)
  /// A converging iteration stops once a full step would lower f by at most this fraction of
  /// max(f, 1), to first order (-grad f . d).
  double converged_decrease = 1e-4;
  double epsilon = 1e-6;                     ///< constraint-block regularisation (rho = 1/epsilon)
  double restoration_epsilon = 1e-6;         ///< of global and local restoration steps
  double polish_epsilon = 1e-8;              ///< of restoration steps when polishing
  double merit_penalty = 1e3;                ///< mu of the fallback line search
  int trusted_backtracks = 3;                ///< halvings with mu = rho before the fallback
  double constraint_tolerance = 5e-5;        ///< |c|_inf wanted after every iteration
  double final_constraint_tolerance = 5e-7;  ///< ... after the last one
  int max_restoration_steps = 20;            ///< per iteration (twice that in the last one)
  int polish_steps = 10;                     ///< exact-Hessian steps of the last iteration
  int polish_factorizations =
      300;  ///< factorisations of a last-iteration polish or projection (0: no limit)
  int projection_steps = 400;  ///< restoration steps of the projection, per phase
  int local_rings = 2;         ///< neighbourhood of a local restoration step
  /// Local steps while at most this share of rows is violated; negative: automatic (0 in the
  /// standard mode with exact stitching, else kDefaultLocalFraction).
  double local_fraction = -1;
  double armijo = 1e-4;                 ///< sufficient decrease factor of the line search
  int max_backtracks = 20;              ///< halvings of the step before giving up
  double regularization = 1e-8;         ///< smallest shift delta of K
  double rho_max = 1e12;                ///< rho may grow to this to make K positive definite
  bool second_order_correction = true;  ///< retry a rejected full step pulled back onto c = 0
  bool lagrangian_hessian = false;      ///< add -sum lambda_i Hess c_i to H
  /// Empty when valid, else the offending field and why.
  std::string validate() const;
};

const OptionTable<SqpOptions>& sqp_option_table();

}  // namespace sdog
