#pragma once
// Work counters of a solver step, added up with += over steps, patches, iterations and runs.
namespace sdog {

struct Work {
  int steps = 0;  ///< optimality (SQP) steps; Ceres iterations for the Ceres patch backend
  int restoration_steps = 0;  ///< steps that only restored the constraints (chord, local, global)
  int local_steps = 0;        ///< of which local (local_restoration.h)
  int factorizations = 0;     ///< global numeric factorisations
  int fold_retries = 0;       ///< iterations solved again with a raised fold bias (standard_mode.h)
  int recovered_failures =
      0;                   ///< failed passes taken back and retried shorter (SqpSolver::converge)
  double factor_ms = 0;    ///< numeric factorisations and triangular solves
  double assembly_ms = 0;  ///< linearisations (Hessians and Jacobians)

  Work& operator+=(const Work& o) {
    steps += o.steps;
    restoration_steps += o.restoration_steps;
    local_steps += o.local_steps;
    factorizations += o.factorizations;
    fold_retries += o.fold_retries;
    recovered_failures += o.recovered_failures;
    factor_ms += o.factor_ms;
    assembly_ms += o.assembly_ms;
    return *this;
  }
};

}  // namespace sdog
