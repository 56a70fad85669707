#pragma once
// The weights of the objective terms, with the thesis's defaults, and their option table.
#include <string>

#include "base/option_table.h"

namespace sdog {

struct Weights {
  double bending = 1;
  double isometry = 20000;  ///< divided by the number of quad edges
  double stitching = 10;
  double positions = 25;
  double edge_points = 25;
  double angles = 1000;
  double fold_bias = 1;
  double link = 0;
  std::string validate() const;
};

const OptionTable<Weights>& weights_option_table();

}  // namespace sdog
