// Setting up a run (run_setup.h): what cannot run is refused before any iteration.
#include <gtest/gtest.h>

#include "base/errors.h"
#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/run/run_setup.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

const DogModel& model() {
  static const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {13, 9});
  return m;
}

TEST(RunSetup, RefusesWhatCannotRunBeforeAnyIteration) {
  RunConfig config;
  config.scenario = ScenarioKind::kNone;  // no targets at all
  EXPECT_THROW(RunSetup(model(), ModeKind::kStandard, config), UsageError);
  MeshOptions fine_only;
  fine_only.build_coarse = false;
  const DogModel even =
      build_dog_model(read_crease_pattern(test::dataset("one_curve.svg")), {14, 10}, fine_only);
  EXPECT_THROW(RunSetup(even, ModeKind::kCoarse, RunConfig()), UsageError);
  RunConfig switching;
  switching.switches = {{5, ModeKind::kTwoLevel}};
  EXPECT_THROW(RunSetup(even, ModeKind::kStandard, switching), UsageError);
  RunConfig bad_vertex;
  PositionSpec p;
  p.path = "c.json: $.positions[0]";
  p.vertex = 100000;
  p.move = Eigen::Vector3d(0, 0, 1);
  bad_vertex.positions.push_back(p);
  try {
    RunSetup setup(model(), ModeKind::kStandard, bad_vertex);
    ADD_FAILURE() << "a vertex that does not exist was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c.json: $.positions[0].vertex"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sdog
