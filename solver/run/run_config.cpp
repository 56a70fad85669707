#include "solver/run/run_config.h"

#include <algorithm>

#include "base/errors.h"
#include "base/text_format.h"

namespace sdog {
void apply_preset(Preset preset, RunConfig& o) {
  const StandardOptions defaults;
  const bool thesis = preset == Preset::kThesis;
  o.weights.angles = thesis ? kThesisAngleWeight : Weights{}.angles;
  o.standard.stitching = thesis ? Stitching::kSoft : defaults.stitching;
  o.standard.sqp.polish_factorizations = thesis ? 0 : defaults.sqp.polish_factorizations;
  o.standard.sqp.projection_steps = thesis ? kThesisProjectionSteps : defaults.sqp.projection_steps;
  o.standard.converge = thesis ? false : defaults.converge;
  o.standard.max_fold_bias = thesis ? 1e14 : defaults.max_fold_bias;
}

const OptionTable<RunConfig>& run_option_table() {
  using C = RunConfig;
  static const OptionTable<C> table = {
      choice_option("preset", &C::preset,
                    "default: exact stitching, converging iterations; thesis: the thesis's solver "
                    "(soft stitching, "
                    "one step per iteration, no factorisation budget for the polish, a shorter "
                    "projection), for its numbers; applied before the other keys (also --preset)"),
      choice_option(
          "scenario", &C::scenario,
          "corners: the thesis protocol; fold: every crease folds from flat to angle; none: only "
          "the "
          "listed constraints; flatten: a folded sheet is left to unfold (also --scenario)"),
      integer_option("iterations", &C::iterations, Bounds::at_least(0),
                     "iterations over which the targets move (also --iters)"),
      integer_option("hold", &C::hold, Bounds::at_least(0),
                     "iterations with the final targets (also --hold)"),
      real_option("angle", &C::fold_angle, Bounds::between(-180, 180),
                  "degrees: the fold scenario's final dihedral angle, the flatten scenario's start "
                  "(also --angle)"),
      real_option("fold_percent", &C::fold_percent, Bounds::between(0, 100),
                  "the fold scenario folds every crease to this percentage of its angle (the "
                  "drawing's, a FOLD "
                  "file's edges_foldAngle, or angle) (also --fold-percent)"),
  };
  return table;
}

void validate_run_config(const RunConfig& c, const std::string& source, ErrorKind kind) {
  if (std::string m = check_option_bounds(run_option_table(), c); !m.empty())
    throw_error(kind, source + ": $." + m);
  if (c.iterations + c.hold < 1)
    throw_error(kind, source + ": iterations + hold must be at least 1");
  if (const std::string m = c.weights.validate(); !m.empty())
    throw_error(kind, source + ": $.weights: " + m);
  if (const std::string m = c.standard.validate(); !m.empty())
    throw_error(kind, source + ": $.solver: " + m);
  if (const std::string m = c.subsolvers.validate(); !m.empty())
    throw_error(kind, source + ": $.patch_solver: " + m);
  if (const std::string m = c.admm.validate(); !m.empty())
    throw_error(kind, source + ": $.admm." + m);
  if (const std::string m = c.coarse.validate(); !m.empty())
    throw_error(kind, source + ": $.coarse." + m);
  if (const std::string m = c.twolevel.validate(); !m.empty())
    throw_error(kind, source + ": $.twolevel." + m);
  for (size_t i = 0; i < c.switches.size(); ++i) {
    const int k = c.switches[i].iteration;
    const std::string where = source + ": $.switches[" + std::to_string(i) + "]: ";
    if (k < 1 || k > c.iterations + c.hold)
      throw_error(kind, where + "iteration " + std::to_string(k) + " is not in the run (1 to " +
                            std::to_string(c.iterations + c.hold) + ")");
    if (i > 0 && k <= c.switches[i - 1].iteration)
      throw_error(kind, where + "switches must be in ascending order of iteration");
  }
}

}  // namespace sdog
