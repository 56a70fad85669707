#pragma once
// The size of the standard mode's continuation sub-steps (standard_mode.h). Target motion is
// measured in sub-steps of the largest size (TargetSteps). A sub-step is kept when its line search
// kept at least `min_step_length` of the full step, or when it is short, and the next one is then
// twice as long (up to the largest); else it is rolled back and the next one is half as long, down
// to kSmallest of the remaining motion.
namespace sdog {

class SubstepSchedule {
 public:
  /// The smallest sub-step (fraction of the remaining motion); when even it is not kept the
  /// iteration leaves the state where it was.
  static constexpr double kSmallest = 1.0 / 1024;
  /// A sub-step that moves the targets at most this fraction of the largest one is short.
  static constexpr double kShort = 1.0 / 4;

  /// `min_step_length`: StandardOptions::substep_step_length.
  explicit SubstepSchedule(double min_step_length) : min_step_length_(min_step_length) {}
  /// Targets that move no further than a short sub-step take one iteration without sub-steps.
  static bool short_move(double distance) { return distance <= kShort; }
  /// The fraction of the `remaining` motion the next sub-step takes (at most the largest sub-step).
  double next(double remaining) const;
  static bool smallest(double s) { return s <= kSmallest; }
  /// Whether the sub-step of fraction `s` of `remaining`, whose solve ended with `step_length`
  /// (or failed), is kept.
  bool keeps(double s, double remaining, bool failed, double step_length) const;
  /// The sub-step was kept: the next may be twice as long.
  void kept();
  /// The sub-step of fraction `s` was rolled back: the next is half as long.
  void rejected(double s);
  /// A fresh start: the next sub-step is the largest.
  void reset() { size_ = 1; }

 private:
  double min_step_length_;
  double size_ = 1;  ///< of the next sub-step, as a fraction of the remaining motion
};

}  // namespace sdog
