#pragma once
// The options of the Ceres patch backend (ceres_patch.h) and their table. Options only: this
// header does not include Ceres.
#include <string>

#include "base/option_table.h"

namespace sdog {

struct CeresPatchOptions {
  double constraint_tolerance = 5e-5;        ///< |c|_inf of the patch's DOG constraints
  double final_constraint_tolerance = 5e-7;  ///< ... in the last iteration of a run
  double initial_penalty = 1e4;              ///< mu of the first solve
  double penalty_growth = 10;
  double max_penalty = 1e12;
  int max_outer = 12;  ///< augmented-Lagrangian updates per solve
  int max_inner = 50;  ///< Ceres iterations per update
  /// Empty when valid, else the offending field and why.
  std::string validate() const;
};

const OptionTable<CeresPatchOptions>& ceres_patch_option_table();

}  // namespace sdog
