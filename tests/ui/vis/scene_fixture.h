#pragma once
// The model and states the scene tests draw, computed once per test executable:
// four_corner_arcs.svg at 21x21 at rest (also with the run's constraints), after 40 iterations of
// the standard mode (corners scenario plus a 60 degree fold of crease 0, so that handles and angle
// sites show), and after 40 iterations of the twolevel mode (a moving coarse mesh for the links).
#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/run/run_config.h"
#include "solver/run/run_setup.h"
#include "tests/test_support.h"
#include "ui/vis/scene_state.h"

namespace sdog::test {

inline const DogModel& arcs_model() {
  static const DogModel model =
      build_dog_model(read_crease_pattern(dataset("four_corner_arcs.svg")), {21, 21});
  return model;
}

/// The thesis preset: its soft stitching leaves the gaps the stitching overlay shows.
inline RunConfig arcs_run_config() {
  RunConfig config;
  config.preset = Preset::kThesis;
  apply_preset(config.preset, config);
  config.scenario = ScenarioKind::kCorners;
  config.iterations = 40;
  config.hold = 0;
  AngleSpec fold;
  fold.path = "test";
  fold.curve = 0;
  fold.end_degrees = 60;
  config.angles.push_back(fold);
  return config;
}

/// The last state of a run of `mode` over the configuration's scenario, with the constraints at
/// their final targets.
inline vis::SceneState run_state(const DogModel& model, ModeKind mode, const RunConfig& config) {
  RunSetup setup(model, mode, config);
  const RunSummary summary = setup.run({});
  EXPECT_FALSE(summary.failed()) << summary.failure;
  return vis::scene_state(setup.problem(), setup.positions(), setup.mode().coarse_positions(),
                          &setup.scenario(), 1);
}

inline const vis::SceneState& arcs_standard_state() {
  static const vis::SceneState state =
      run_state(arcs_model(), ModeKind::kStandard, arcs_run_config());
  return state;
}

/// The flat sheet with the constraints of the standard run at their final targets.
inline const vis::SceneState& arcs_rest_state_with_targets() {
  static const vis::SceneState state = [] {
    const Scenario scenario = make_scenario(arcs_run_config(), arcs_model().fine);
    return vis::rest_scene_state(arcs_model(), &scenario);
  }();
  return state;
}

inline const vis::SceneState& arcs_twolevel_state() {
  static const vis::SceneState state = [] {
    RunConfig config = arcs_run_config();
    config.angles.clear();                // the coarse level does not carry angle constraints
    config.twolevel.standard_finish = 0;  // the coarse mesh moves to the end (the links picture)
    return run_state(arcs_model(), ModeKind::kTwoLevel, config);
  }();
  return state;
}

}  // namespace sdog::test
