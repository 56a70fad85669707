// Workspaces (workspace.h): a session saved and loaded back, and bad files refused with the path.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "base/errors.h"
#include "geometry/mesh/dog_model.h"
#include "solver/session/session.h"
#include "solver/session/workspace.h"
#include "tests/solver/session_fixture.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

const DogModel& model() {
  return test::session_model();
}
using test::interactive;

TEST(Workspace, SavedAndLoadedBackGivesTheSameSession) {
  RunConfig config = interactive();
  config.weights.bending = 2;
  Session s(model(), config, ModeKind::kStandard);
  s.add_handle(0);
  s.add_handle(7);
  s.move_handle(1, Eigen::Vector3d(1, 2, 3));
  for (int k = 0; k < 3; ++k) ASSERT_FALSE(s.step().step.failed);
  const std::string dir = test::temp_dir("workspace");
  const nlohmann::json camera = {{"position", {1, 2, 3}}, {"focal_point", {0, 0, 0}}};
  save_workspace(workspace_of(s, "../somewhere/four_corner_arcs.svg", "21x21", camera),
                 dir + "/w.json");
  const Workspace w = load_workspace(dir + "/w.json");
  EXPECT_EQ(w.pattern, (std::filesystem::path(dir) / "../somewhere/four_corner_arcs.svg")
                           .lexically_normal()
                           .string());
  EXPECT_EQ(w.resolution, "21x21");
  EXPECT_EQ(w.mode, "standard");
  EXPECT_EQ(w.iteration, 3);
  EXPECT_EQ(w.camera, camera);
  EXPECT_EQ(w.config.weights.bending, 2);
  EXPECT_EQ(w.config.scenario, ScenarioKind::kNone);
  ASSERT_EQ(w.constraints.handles.size(), 2u);
  EXPECT_EQ(w.constraints.handles[1].target, Eigen::Vector3d(1, 2, 3));
  EXPECT_LT((w.positions - s.positions()).lpNorm<Eigen::Infinity>(), 1e-12);

  Session back(model(), w.config, parse_enum<ModeKind>(w.mode));
  back.set_constraints(w.constraints);
  back.set_positions(w.positions, w.iteration);
  EXPECT_EQ(back.scenario().positions.size(), 2u);
  EXPECT_EQ(back.iteration(), 3);
  // The same next iteration as the saved session's after a restart of its solver (a loaded
  // session's solver starts with zero multipliers).
  s.set_mode(ModeKind::kStandard);
  const IterationReport a = s.step(), b = back.step();
  EXPECT_NEAR(a.diagnostics.objective, b.diagnostics.objective,
              1e-9 * (1 + a.diagnostics.objective));
  EXPECT_THROW(back.set_positions(Dofs::Zero(6), 0), InputError);
}

TEST(Workspace, BadFilesAreErrorsNamingThePath) {
  const std::string dir = test::temp_dir("workspace_bad");
  auto error_of = [&](const std::string& text) {
    const std::string path = test::write_file(dir, "w.json", text);
    try {
      load_workspace(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("{").find("not valid JSON"), std::string::npos);
  EXPECT_NE(error_of(R"({"format": "x"})").find("$.format"), std::string::npos);
  const std::string head =
      R"({"format": "sdog-workspace", "version": 1, "pattern": "p.svg", "resolution": "21x21", "mode": "standard", )";
  EXPECT_NE(error_of(head + R"("handles": [{"vertex": 1, "target": [1, 2]}]})")
                .find("$.handles[0].target"),
            std::string::npos);
  EXPECT_NE(error_of(head + R"("colour": 1})").find("$.colour"), std::string::npos);
  EXPECT_NE(error_of(head + R"("config": {"weights": {"bending": -1}}})").find("bending"),
            std::string::npos);
  EXPECT_EQ(error_of(head + R"("positions": []})"), "no error");
  EXPECT_THROW(save_workspace(Workspace{}, "/proc/forbidden/w.json"), OutputError);
}

}  // namespace
}  // namespace sdog
