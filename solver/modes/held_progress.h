#pragma once
// When held targets count as converged without the solver saying so (standard_mode.h): steps that
// cycle, or a crease that unfolds in every iteration and is refolded by the fold-bias retry, keep
// an iteration from converging although the objective no longer falls. The state counts as
// converged once kHeldWithoutProgress held iterations in a row have not lowered the objective by
// more than a relative margin below its lowest value since the targets last moved.
#include <optional>

namespace sdog {

class HeldProgress {
 public:
  static constexpr int kHeldWithoutProgress = 5;
  /// `decrease`: the relative margin (SqpOptions::converged_decrease; at least `decrease` in
  /// absolute terms for objectives below 1).
  explicit HeldProgress(double decrease) : decrease_(decrease) {}
  /// The targets moved: the count starts again.
  void reset() { best_.reset(); }
  /// After a held iteration that has not converged, with objective f: false once
  /// kHeldWithoutProgress of them in a row have not lowered the lowest objective by the margin.
  bool lowers(double f);

 private:
  double decrease_;
  std::optional<double> best_;  ///< lowest objective of the held iterations since a move
  int without_progress_ = 0;    ///< held iterations in a row that did not lower it
};

}  // namespace sdog
