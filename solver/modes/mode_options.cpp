#include "solver/modes/mode_options.h"

#include <cmath>

namespace sdog {

const OptionTable<StandardOptions>& standard_option_table() {
  using O = StandardOptions;
  static const OptionTable<O> table = concatenate(
      nested_options(&O::sqp, sqp_option_table()),
      OptionTable<O>{
          boolean_option(
              "folding", &O::folding,
              "an iteration that leaves a crease unfolded is solved again with a raised fold bias"),
          real_option("max_fold_bias", &O::max_fold_bias, Bounds::positive(),
                      "the fold-bias weight is raised at most to this"),
          boolean_option("converge", &O::converge,
                         "converging iterations: moving targets are followed in sub-steps, held "
                         "ones are solved "
                         "until converged, then cost nothing (off: max_steps steps per iteration, "
                         "the thesis)"),
          integer_option(
              "max_iteration_steps", &O::max_iteration_steps, Bounds::at_least(1),
              "SQP steps of a converging iteration at most (towards convergence when the targets "
              "hold, continuation sub-steps when they moved)"),
          real_option(
              "max_target_step", &O::max_target_step, Bounds::positive(),
              "a converging iteration moves each target at most this fraction of the sheet's size"),
          real_option(
              "max_angle_step", &O::max_angle_step, Bounds::positive(),
              "a converging iteration moves each dihedral-angle target at most this many degrees"),
          real_option(
              "substep_step_length", &O::substep_step_length, Bounds::between(0, 1),
              "a sub-step towards moved targets is kept when its line search kept at least this "
              "fraction of the full step; else it is halved"),
          real_option("substep_constraint_tolerance", &O::substep_constraint_tolerance,
                      Bounds::positive(),
                      "between the continuation sub-steps of one iteration, restoration stops once "
                      "the largest "
                      "DOG constraint residual is within this; the iteration ends within "
                      "constraint_tolerance"),
          boolean_option(
              "settle", &O::settle,
              "once the targets rest and the shape has converged, also fold from the run's start "
              "state straight to them and keep the fold with the lower objective (converging "
              "iterations only)"),
          choice_option(
              "stitching", &O::stitching,
              "exact: the copies of a crease point coincide as hard constraints; soft: only the "
              "stitching term pulls them together (the thesis)"),
      });
  return table;
}

const OptionTable<SubsolverOptions>& subsolver_option_table() {
  using O = SubsolverOptions;
  static const OptionTable<O> table = concatenate(
      OptionTable<O>{
          choice_option(
              "backend", &O::backend,
              "how a patch step is solved: sqp (the standard solver on the patch) or ceres"),
          choice_option(
              "sweep", &O::sweep,
              "jacobi: every patch steps from the same state; colours: the patch graph's colours "
              "one after another"),
      },
      nested_options(&O::patch, ceres_patch_option_table()));
  return table;
}

const OptionTable<CoarseOptions>& coarse_option_table() {
  using O = CoarseOptions;
  static const OptionTable<O> table = {
      real_option("link_weight", &O::link_weight, Bounds::at_least(0),
                  "weight of the link targets between fine and coarse twins (also --link-weight)"),
      boolean_option(
          "fine_to_coarse", &O::fine_to_coarse,
          "the coarse link vertices are pulled towards their fine twins (--no-fine-to-coarse)"),
      boolean_option("prolongate", &O::prolongate,
                     "every fine step starts from the coarse state carried to the fine mesh"),
      boolean_option("concurrent_coarse", &O::concurrent_coarse,
                     "the next iteration's coarse step runs beside this iteration's fine round "
                     "(same results)"),
  };
  return table;
}

const OptionTable<TwoLevelOptions>& twolevel_option_table() {
  using O = TwoLevelOptions;
  static const OptionTable<O> table = {
      real_option("link_weight", &O::link_weight, Bounds::at_least(0),
                  "pull of the coarse link vertices towards their fine twins (also --link-weight)"),
      real_option(
          "fold_sharpness", &O::fold_sharpness, Bounds::positive(),
          "sharpness k of the fold bias tanh(k B.e) in the coarse step and the fine patches"),
      integer_option("standard_finish", &O::standard_finish, Bounds::at_least(0),
                     "the run's last iterations computed by the standard solver (0: none)"),
      real_option(
          "finish_fold_bias_cap", &O::finish_fold_bias_cap, Bounds::at_least(1),
          "the finish's fold retries raise the fold bias at most to this multiple of its weight"),
      boolean_option("concurrent_coarse", &O::concurrent_coarse,
                     "the next iteration's coarse step runs beside this iteration's fine round "
                     "(same results)"),
      integer_option("coarse_every", &O::coarse_every, Bounds::at_least(1),
                     "a coarse step every this many iterations, its displacement spread over them"),
  };
  return table;
}

const OptionTable<AdmmOptions>& admm_option_table() {
  using O = AdmmOptions;
  // p is negative while unset (the default depends on the mesh).
  Option<O> p{"p",
              OptionType::kReal,
              Bounds::at_least(0),
              {},
              "proxjadmm: proximal weight P = p I",
              "0.001 (patches - 1)",
              [](const O& o) { return o.p >= 0 ? std::optional<double>(o.p) : std::nullopt; },
              [](O& o, std::optional<double> v) { o.p = v ? *v : -1; }};
  static const OptionTable<O> table = {
      real_option("rho", &O::rho, Bounds::positive(),
                  "penalty of the augmented terms (also --rho)"),
      real_option("gamma", &O::gamma, Bounds::positive(),
                  "jadmm, proxjadmm: damping of the multiplier update (also --gamma)"),
      p,
      integer_option("inner", &O::inner, Bounds::at_least(1), "ADMM rounds per solver iteration"),
  };
  return table;
}

std::string StandardOptions::validate() const {
  if (const std::string m = sqp.validate(); !m.empty()) return m;
  if (std::string m = check_option_bounds(standard_option_table(), *this); !m.empty()) return m;
  if (blas_threads < 0) return "blas_threads must be at least 0";
  return "";
}

std::string SubsolverOptions::validate() const {
  if (!(fold_sharpness >= 0) || !std::isfinite(fold_sharpness))
    return "fold_sharpness must be at least 0";
  if (std::string m = check_option_bounds(subsolver_option_table(), *this); !m.empty()) return m;
  return patch.validate();
}

std::string CoarseOptions::validate() const {
  return check_option_bounds(coarse_option_table(), *this);
}

std::string TwoLevelOptions::validate() const {
  return check_option_bounds(twolevel_option_table(), *this);
}

std::string AdmmOptions::validate() const {
  return check_option_bounds(admm_option_table(), *this);
}

double AdmmOptions::proximal_weight(int patches) const {
  return p >= 0 ? p : 0.001 * (patches - 1);
}

}  // namespace sdog
