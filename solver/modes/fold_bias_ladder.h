#pragma once
// The fold-bias ladder of the standard mode's folding (standard_mode.h): after an iteration that
// leaves the sheet unfolded, the fold-bias weight climbs by kGrowth per rung up to a cap and the
// iteration is solved again on each rung; a folded iteration brings it back to its base weight.
// The ladder owns the weight's rungs and says when a converging iteration stops climbing; the
// solves on each rung are the mode's.
#include <functional>

namespace sdog {

class FoldBiasLadder {
 public:
  /// Each rung multiplies the weight by this.
  static constexpr double kGrowth = 10;
  /// `install` puts a weight into the problem and the solver. `base`: the weight the problem was
  /// built with; `max`: the highest rung (StandardOptions::max_fold_bias).
  FoldBiasLadder(double base, double max, std::function<void(double)> install);

  double base() const { return base_; }
  /// Installs the base weight.
  void to_base() { install_(base_); }
  /// Installs weight 0 (folding off).
  void off() { install_(0); }
  /// The next rung above `weight`: the weight raised kGrowth times and installed, true; false
  /// (nothing installed) once that would pass the cap or the weight is not positive.
  bool raise(double& weight);

  /// A converging iteration starts: its sub-steps may climb again.
  void new_iteration() { climbed_in_vain_ = false; }
  /// A climb of this iteration ended with the sheet still unfolded: its later sub-steps take none
  /// (each would climb the whole ladder again, a solve per rung).
  void climb_failed() { climbed_in_vain_ = true; }
  bool may_climb() const { return !climbed_in_vain_; }

 private:
  double base_, max_;
  std::function<void(double)> install_;
  bool climbed_in_vain_ = false;
};

}  // namespace sdog
