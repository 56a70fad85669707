#pragma once
// Residual blocks as Ceres cost functions: one parameter block (3 coordinates) per vertex of the
// block, residuals scaled by sqrt(weight) so that Ceres' 1/2 |r|^2 sums match
// weight * |r|^2 / 2. An optional offset o (one value per residual, owned by the caller) makes the
// residual sqrt(weight) (r - o): the augmented-Lagrangian form mu/2 |c - lambda/mu|^2 of a
// constraint block. Weight and offset may change between solves, not during one.
#include <ceres/ceres.h>

#include "solver/terms/term.h"

namespace sdog {

class TermCost : public ceres::CostFunction {
 public:
  TermCost(const Term& term, int block, double weight, const double* offset = nullptr);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;
  void set_weight(double weight);

 private:
  const Term& term_;
  int block_;
  double scale_;
  const double* offset_;
};

/// Functor for ceres::DynamicAutoDiffCostFunction over any term with a templated `residual`.
template <class TermT>
struct TermResidualFunctor {
  const TermT* term;
  int block;
  template <class T>
  bool operator()(T const* const* p, T* r) const {
    term->template residual<T>(block, p, r);
    return true;
  }
};

}  // namespace sdog
