#pragma once
// The standard mode: the global SQP solver (sqp_solver.h) on the whole fine DOG, in folding mode
// by default: after an iteration that leaves the sheet unfolded (check_folded), x is rolled back,
// the fold-bias weight multiplied by 10 and the iteration solved again, up to a weight of 1e14;
// after a folded iteration the weight returns to its base value. When no weight folds the sheet, the
// iteration keeps its attempt with the fewest unfolded sites (among those meeting the constraints as
// well as the first attempt) and the base weight. Off for scenarios that unfold
// (Scenario::keeps_folds false).
#include <memory>

#include "solver/modes/mode.h"
#include "solver/sqp/sqp_solver.h"

namespace sdog {

struct StandardOptions {
  SqpOptions sqp;
  bool folding = true;
  double max_fold_bias = 1e14;
  /// BLAS threads of the factorisations (blas_threads.h); 0: default_blas_threads(). The coarse
  /// step of the two-resolution modes, which may run beside the patch solves, uses 1
  /// (coarse_level.h).
  int blas_threads = 0;
  std::string validate() const;
};

class StandardMode : public Mode {
 public:
  /// The problem must outlive the mode; the scenario is installed into it.
  StandardMode(DogProblem& problem, const Scenario& scenario, const StandardOptions& options);
  const char* name() const override { return "standard"; }
  void set_time(double t) override;
  StepReport iterate(Dofs& x, bool last) override;
  /// Zero multipliers and the base fold bias: a fresh start from x.
  void start_from(const Dofs& x) override;
  /// Folding mode on (fold bias at its base weight, fold check and retries) or off (no fold bias).
  void set_folding(bool on);
  SqpSolver& sqp() { return *sqp_; }

 private:
  void set_fold_bias(double weight);
  DogProblem& problem_;
  Scenario scenario_;
  StandardOptions options_;
  std::unique_ptr<SqpSolver> sqp_;
  double base_fold_bias_;
};

}  // namespace sdog
