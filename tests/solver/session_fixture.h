#pragma once
// The model and configuration of the session and workspace tests.
#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/run/run_config.h"
#include "tests/test_support.h"

namespace sdog::test {

inline const DogModel& session_model() {
  static const DogModel m =
      build_dog_model(read_crease_pattern(dataset("four_corner_arcs.svg")), {21, 21});
  return m;
}

/// A configuration with nothing but the user's constraints.
inline RunConfig interactive() {
  RunConfig c;
  c.scenario = ScenarioKind::kNone;
  return c;
}

}  // namespace sdog::test
