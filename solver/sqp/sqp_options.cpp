#include "solver/sqp/sqp_options.h"

namespace sdog {

const OptionTable<SqpOptions>& sqp_option_table() {
  using S = SqpOptions;
  static const OptionTable<S> table = {
      real_option("kkt_tolerance", &S::kkt_tolerance, Bounds::positive(),
                  "an iteration takes optimality steps until max(|grad f - J^T lambda|_inf, "
                  "|c|_inf) is below this"),
      integer_option("max_steps", &S::max_steps, Bounds::at_least(1),
                     "optimality (SQP) steps per iteration at most"),
      real_option("converged_decrease", &S::converged_decrease, Bounds::positive(),
                  "a converging iteration has converged once a full step would lower the objective "
                  "by at most "
                  "this fraction of max(objective, 1), to first order, or once five held "
                  "iterations in a row have not "
                  "lowered it by more than that"),
      real_option("epsilon", &S::epsilon, Bounds::positive(),
                  "regularisation of the KKT system's constraint block (rho = 1/epsilon)"),
      real_option("restoration_epsilon", &S::restoration_epsilon, Bounds::positive(),
                  "regularisation of the restoration steps"),
      real_option(
          "polish_epsilon", &S::polish_epsilon, Bounds::positive(),
          "regularisation of the restoration steps of the last iteration's polish and projection"),
      real_option("merit_penalty", &S::merit_penalty, Bounds::positive(),
                  "penalty mu of the fallback line search (nearly flat regions)"),
      integer_option("trusted_backtracks", &S::trusted_backtracks, Bounds::at_least(0),
                     "halvings of the step with mu = rho before the fallback line search"),
      real_option("constraint_tolerance", &S::constraint_tolerance, Bounds::positive(),
                  "largest DOG constraint residual wanted after every iteration"),
      real_option("final_constraint_tolerance", &S::final_constraint_tolerance, Bounds::positive(),
                  "largest DOG constraint residual wanted after the last iteration"),
      integer_option("max_restoration_steps", &S::max_restoration_steps, Bounds::at_least(0),
                     "restoration steps per iteration at most (twice that in the last)"),
      integer_option("polish_steps", &S::polish_steps, Bounds::at_least(0),
                     "exact-Hessian steps of the last iteration's polish at most"),
      integer_option(
          "polish_factorizations", &S::polish_factorizations, Bounds::at_least(0),
          "factorisations of the last iteration's polish and projection at most (0: no limit)"),
      integer_option("projection_steps", &S::projection_steps, Bounds::at_least(1),
                     "restoration steps of the last iteration's projection at most, then as many "
                     "more with local "
                     "steps if that stops short"),
      integer_option(
          "local_rings", &S::local_rings, Bounds::at_least(0),
          "rings of neighbours around the violated rows that a local restoration step moves"),
      real_option(
          "local_fraction", &S::local_fraction, Bounds::between(-1, 1),
          "local restoration steps while at most this share of the constraint rows is violated; "
          "negative: automatic (none in the standard mode with exact stitching, else 0.1)"),
      real_option("armijo", &S::armijo, Bounds::open(0, 0.5),
                  "sufficient-decrease factor of the line search"),
      integer_option("max_backtracks", &S::max_backtracks, Bounds::at_least(0),
                     "halvings of a step before the line search gives up"),
      real_option("regularization", &S::regularization, Bounds::at_least(0),
                  "smallest diagonal shift of the factorised matrix"),
      real_option("rho_max", &S::rho_max, Bounds::positive(),
                  "rho may grow to this to make the factorised matrix positive definite"),
      boolean_option("second_order_correction", &S::second_order_correction,
                     "retry a rejected full step pulled back onto the constraints"),
      boolean_option(
          "lagrangian_hessian", &S::lagrangian_hessian,
          "add the constraints' curvature to the Hessian in every step (off: only in the polish)"),
  };
  return table;
}

std::string SqpOptions::validate() const {
  if (std::string m = check_option_bounds(sqp_option_table(), *this); !m.empty()) return m;
  if (!(rho_max >= 1 / epsilon) || !(rho_max >= 1 / restoration_epsilon) ||
      !(rho_max >= 1 / polish_epsilon))
    return "rho_max must be at least 1/epsilon, 1/restoration_epsilon and 1/polish_epsilon";
  return "";
}

}  // namespace sdog
