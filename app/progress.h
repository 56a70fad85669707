#pragma once
// A one-line progress bar on stderr (only when stderr is a terminal): iteration, scenario time,
// objective, DOG constraint maximum, speed and remaining time.
#include <chrono>

#include "solver/run/run.h"

namespace sdog::cli {

class ProgressBar : public RunObserver {
 public:
  /// `total` iterations; `enabled` false turns it off (e.g. --quiet).
  ProgressBar(int total, bool enabled);
  ~ProgressBar() override;
  void on_iteration(const IterationReport& r, const Dofs&) override;
  /// Clears the line.
  void finish();

 private:
  int total_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace sdog::cli
