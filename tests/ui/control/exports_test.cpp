// Exports and recordings of the studio without a window (ui/control/exports.h, recorder.h): the
// surface files and a recording of VTK frames (the PNG paths need a display: the studio tests).
#include "ui/control/exports.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/errors.h"
#include "tests/ui/vis/scene_fixture.h"
#include "ui/control/recorder.h"

namespace sdog::control {
namespace {
namespace fs = std::filesystem;

int lines_starting(const std::string& path, const std::string& prefix) {
  std::ifstream in(path);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0;
  return n;
}

TEST(Exports, WritesTheSurfaceAsThePathSaysAndAppendsObjOtherwise) {
  const std::string dir = test::temp_dir("control_exports");
  const DogModel& model = test::arcs_model();
  const vis::SceneState& state = test::arcs_standard_state();
  const std::string obj = export_surface(model, state, vis::Layer::kPatches, dir + "/sheet");
  EXPECT_EQ(obj, dir + "/sheet.obj");
  EXPECT_GT(lines_starting(obj, "v "), model.fine.vertex_count() / 2);
  EXPECT_GT(lines_starting(obj, "f "), 0);
  const std::string ply = export_surface(model, state, vis::Layer::kBending, dir + "/sheet.PLY");
  EXPECT_EQ(ply, dir + "/sheet.PLY");
  EXPECT_EQ(lines_starting(ply, "ply"), 1);
  EXPECT_EQ(export_surface(model, state, vis::Layer::kPatches, dir + "/new/folder/s.obj"),
            dir + "/new/folder/s.obj")
      << "missing folders are made";
  EXPECT_THROW(export_surface(model, state, vis::Layer::kPatches, obj + "/s.obj"), OutputError)
      << "under a file";
  EXPECT_FALSE(fs::exists(dir + "/sheet.obj/s.obj"));
  EXPECT_EQ(with_extension("a/b", "png"), "a/b.png");
  EXPECT_EQ(with_extension("a.b/c.jpg", "png"), "a.b/c.jpg");
}

TEST(Recorder, RecordsDueStatesAsFramesAndSaysWhereTheyWent) {
  const std::string dir = test::temp_dir("control_recording");
  RecordingOptions options;
  options.png = false;
  options.vtu = true;
  options.every = 2;
  Recorder recorder(test::arcs_model(), dir, options);
  for (int iteration = 0; iteration <= 4; ++iteration)
    if (recorder.due(iteration))
      recorder.record(test::arcs_standard_state(), iteration, 0.25 * iteration, {});
  EXPECT_EQ(recorder.frame_count(), 3) << "iterations 0, 2 and 4";
  EXPECT_TRUE(fs::exists(dir + "/frame_0002.vtu"));
  EXPECT_FALSE(fs::exists(dir + "/frame_0000.png"));
  EXPECT_EQ(lines_starting(dir + "/frames.csv", ""), 4) << "a header and three frames";
  EXPECT_EQ(recording_indicator(recorder).rfind("\u25CF REC 3 frames, ", 0), 0u)
      << recording_indicator(recorder);
  const std::string summary = recording_summary(recorder, "/there");
  EXPECT_EQ(summary.rfind("recording stopped: 3 frames (", 0), 0u) << summary;
  EXPECT_NE(summary.find(" in /there (frames.csv lists their iterations)"), std::string::npos)
      << summary;
  options.vtu = false;
  EXPECT_THROW(Recorder(test::arcs_model(), dir + "/nothing", options), UsageError)
      << "nothing chosen";
}

}  // namespace
}  // namespace sdog::control
