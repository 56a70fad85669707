#pragma once
// The weights of the objective terms, with the thesis's defaults but for the angles (the thesis
// weighs its cosine form 1000; the signed form at 100 folds designs drawn elsewhere to the same
// angles, degrees apart at most, with a tenth of the factorisations: docs/design/rejected.md),
// and their option table.
#include <string>

#include "base/option_table.h"

namespace sdog {

struct Weights {
  double bending = 1;
  double isometry = 20000;  ///< divided by the number of quad edges
  double stitching = 10;
  double positions = 25;
  double edge_points = 25;
  double angles = 100;
  double fold_bias = 1;
  double link = 0;
  std::string validate() const;
};

const OptionTable<Weights>& weights_option_table();

}  // namespace sdog
