#pragma once
// The pace benchmark (sdog bench --pace): the corners scenario with its final targets reached
// after K iterations (K = 250 is the thesis protocol, K = 1 sets them at once), then held until
// an iteration reports the shape converged, and a last iteration that finishes it. The fold
// benchmark (sdog bench --fold) does the same with the fold scenario.
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "solver/problem/diagnostics.h"
#include "solver/run/run_config.h"

namespace sdog {

struct PaceResult {
  int k = 0;  ///< iterations over which the targets move
  int iterations = 0;
  double objective = 0;
  double dog_max = 0;
  double stitch_gap_max = 0;
  double sheet_strain_max = 0;  ///< largest strain of the paper (Diagnostics::sheet_strain_max)
  bool folded = false;
  double handle_distance = 0;  ///< largest distance of a handle to its target, mesh units
  double positions = 0;        ///< the positions term
  long factorizations = 0;
  /// Wall time until the first converged iteration after the targets stopped moving; none when
  /// no held iteration converged.
  std::optional<double> time_to_shape_s;
  double total_s = 0;
  /// The fold sites against their angle targets at the end (the fold scenario).
  AngleAgreement angles;
  bool converged =
      false;  ///< the last iteration converged: after a converged one, it met the final tolerance
  std::string failure;  ///< empty unless an iteration failed
};

/// The standard mode on `model` with `config`'s solver settings, the corners scenario moving over
/// k iterations, then at most max_hold held ones until converged.
PaceResult run_pace(const DogModel& model, RunConfig config, int k, int max_hold);

/// The same with the fold scenario (config's fold angle and fold percent): every crease folds from
/// flat to its target over k iterations, then at most max_hold held ones until converged.
PaceResult run_fold_pace(const DogModel& model, RunConfig config, int k, int max_hold);

/// The objective of each result over the best (lowest) objective of the results that did not fail.
std::vector<double> objective_ratios(const std::vector<PaceResult>& results);

}  // namespace sdog
