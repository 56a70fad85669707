#pragma once
// A term of an objective with its weight: the objective is sum_k weight_k |r_k(x)|^2.
#include "solver/terms/term.h"

namespace sdog {

struct WeightedTerm {
  const Term* term;
  double weight;
  bool exact_hessian;  ///< 2 (J^T J + sum y Hess r) instead of Gauss-Newton 2 J^T J
};

}  // namespace sdog
