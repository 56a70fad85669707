#include "solver/modes/settling_plan.h"

#include <utility>

namespace sdog {

SettlingPlan::SettlingPlan(bool on, std::optional<Dofs> origin)
    : on_(on), origin_(std::move(origin)), origin_given_(origin_.has_value()) {}

void SettlingPlan::begin_iteration(const Dofs& x) {
  if (goals_ == 0) away_from_origin_ = origin_ && *origin_ != x;
  if (!origin_) origin_ = x;
}

void SettlingPlan::new_goal() {
  ++goals_;
  settled_ = false;
}

bool SettlingPlan::wanted() const {
  return on_ && !settled_ && (goals_ > 1 || away_from_origin_);
}

void SettlingPlan::restart() {
  if (!origin_given_) origin_.reset();
  goals_ = 0;
  settled_ = false;
}

bool straight_fold_wins(const SettledFold& run, const SettledFold& straight, double margin) {
  if (!straight.folded) return false;
  if (straight.against != run.against) return straight.against < run.against;
  return !run.folded || straight.objective < run.objective - margin;
}

}  // namespace sdog
