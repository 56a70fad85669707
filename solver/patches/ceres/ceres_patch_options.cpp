#include "solver/patches/ceres/ceres_patch_options.h"

namespace sdog {

const OptionTable<CeresPatchOptions>& ceres_patch_option_table() {
  using O = CeresPatchOptions;
  static const OptionTable<O> table = {
      real_option("constraint_tolerance", &O::constraint_tolerance, Bounds::positive(),
                  "ceres backend: largest DOG constraint residual of a patch after a solve"),
      real_option("final_constraint_tolerance", &O::final_constraint_tolerance, Bounds::positive(),
                  "ceres backend: the same in the run's last iteration"),
      real_option("initial_penalty", &O::initial_penalty, Bounds::positive(),
                  "ceres backend: augmented-Lagrangian penalty of the first solve"),
      real_option(
          "penalty_growth", &O::penalty_growth, Bounds::above(1),
          "ceres backend: factor of the penalty when the constraints do not fall fast enough"),
      real_option("max_penalty", &O::max_penalty, Bounds::positive(),
                  "ceres backend: largest penalty"),
      integer_option("max_outer", &O::max_outer, Bounds::at_least(1),
                     "ceres backend: augmented-Lagrangian updates per solve at most"),
      integer_option("max_inner", &O::max_inner, Bounds::at_least(1),
                     "ceres backend: Ceres iterations per update at most"),
  };
  return table;
}

std::string CeresPatchOptions::validate() const {
  if (std::string m = check_option_bounds(ceres_patch_option_table(), *this); !m.empty()) return m;
  if (!(max_penalty >= initial_penalty)) return "max_penalty must be at least initial_penalty";
  return "";
}

}  // namespace sdog
