#include "solver/modes/fold_bias_ladder.h"

#include <utility>

namespace sdog {

FoldBiasLadder::FoldBiasLadder(double base, double max, std::function<void(double)> install)
    : base_(base), max_(max), install_(std::move(install)) {}

bool FoldBiasLadder::raise(double& weight) {
  if (!(weight > 0 && weight * kGrowth <= max_)) return false;
  install_(weight *= kGrowth);
  return true;
}

}  // namespace sdog
