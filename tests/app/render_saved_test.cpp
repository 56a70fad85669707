// sdog render of a state a run saved (--frame FILE.vtu, --run DIR --iteration N): the overlays are
// those the run computed at that iteration, --run and --frame draw the same picture, a pattern
// given on the command line must fit the frame, and bad input is refused with one line naming the
// file and nothing written.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/saved_state.h"
#include "tests/app/run_sdog.h"
#include "tests/ui/vis/image_compare.h"

namespace sdog {
namespace {

namespace fs = std::filesystem;

const std::string kArcs = test::dataset("four_corner_arcs.svg");
const std::string kPicture = " --overlay dog-residual,handles --view 3d --size 480x300";

// One run for the tests of a process: 20 iterations of the corners scenario and 5 held, frames
// 0, 10, 20 and 25.
class RenderSaved : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    run_ = test::temp_dir("render_saved_run") + "/run";
    const auto r = test::run_sdog(
        "run '" + kArcs + "' --res 21x21 --iters 20 --hold 5 --frames-every 10 -q --out " + run_);
    ASSERT_EQ(r.code, 0) << r.err;
  }
  static std::string frame(int iteration) {
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%04d.vtu", iteration);
    return run_ + name;
  }
  // Renders `args` into a fresh directory; returns the run and the picture's path.
  static std::pair<test::Run, std::string> render(const std::string& args,
                                                  const std::string& name) {
    const std::string out = test::temp_dir(name) + "/picture.png";
    return {test::run_sdog("render " + args + " --out " + out), out};
  }
  // A copy of the run's folder without the files named in `leave_out`.
  static std::string copy_of_run(const std::string& name,
                                 const std::vector<std::string>& leave_out) {
    const std::string dir = test::temp_dir(name);
    for (const auto& e : fs::directory_iterator(run_))
      if (std::find(leave_out.begin(), leave_out.end(), e.path().filename().string()) ==
          leave_out.end())
        fs::copy(e.path(), dir / e.path().filename());
    return dir;
  }
  static std::string run_;
};
std::string RenderSaved::run_;

vtkSmartPointer<vtkUnstructuredGrid> read_grid(const std::string& path) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

std::vector<double> values(vtkDataArray* a) {
  std::vector<double> out;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) out.push_back(a->GetComponent(i, 0));
  return out;
}

// Every failure: the exit code, one line on stderr containing each of `words`, no picture.
void expect_refused(const std::pair<test::Run, std::string>& r, int code,
                    const std::vector<std::string>& words) {
  EXPECT_EQ(r.first.code, code) << r.first.err;
  EXPECT_EQ(test::count_lines(r.first.err), 1) << r.first.err;
  for (const auto& w : words)
    EXPECT_NE(r.first.err.find(w), std::string::npos) << "'" << w << "' in " << r.first.err;
  EXPECT_TRUE(fs::is_empty(fs::path(r.second).parent_path())) << "output left in " << r.second;
}

// The state drawn for frame 10 against what the run wrote into that frame: the positions, the
// fields of the colour overlays, and the handles' targets of iteration 10 (the frame's
// position_residual is each handle's distance to the target the run pulled it to).
TEST_F(RenderSaved, TheStateIsTheRunsAtThatIteration) {
  cli::SavedStateRequest request;
  request.frame = frame(10);
  request.given = [](const std::string&) { return false; };
  const cli::SavedState saved = cli::load_saved_state(request);
  ASSERT_TRUE(saved.run);
  ASSERT_EQ(saved.iteration, 10);
  const DogModel model = cli::saved_state_model(saved);
  const vis::SceneState state = cli::saved_scene_state(saved, model, saved.run->config, true);

  const auto grid = read_grid(frame(10));
  ASSERT_EQ(state.fine.rows(), grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(state.fine(i, k), grid->GetPoint(i)[k]) << "vertex " << i;
  auto expect_same = [](const std::vector<double>& drawn, vtkDataArray* saved_array,
                        const char* name) {
    ASSERT_NE(saved_array, nullptr) << name;
    const std::vector<double> run = values(saved_array);
    ASSERT_EQ(drawn.size(), run.size()) << name;
    for (size_t i = 0; i < run.size(); ++i)
      EXPECT_NEAR(drawn[i], run[i], 1e-12 * (1 + std::abs(run[i]))) << name << " " << i;
  };
  expect_same(state.fields.dog_residual, grid->GetPointData()->GetArray("dog_residual"),
              "dog_residual");
  expect_same(state.fields.bending, grid->GetPointData()->GetArray("bending"), "bending");
  expect_same(state.fields.edge_strain, grid->GetCellData()->GetArray("edge_strain"),
              "edge_strain");

  const std::vector<double> to_target = values(grid->GetPointData()->GetArray("position_residual"));
  ASSERT_EQ(state.constraints.handles.size(), 2u);
  double moved = 0;
  for (const auto& h : state.constraints.handles) {
    const double distance = (state.fine.row(h.vertex).transpose() - h.target).norm();
    EXPECT_NEAR(distance, to_target[h.vertex], 1e-9) << "handle at vertex " << h.vertex;
    moved = std::max(moved, (h.target - model.fine.V.row(h.vertex).transpose()).norm());
  }
  // The dragged corner's target of iteration 10 is half way: far from both its start and its end.
  const vis::SceneState last = cli::saved_scene_state(
      cli::load_saved_state({frame(25), "", {}, {}, [](const std::string&) { return false; }}),
      model, saved.run->config, true);
  double to_end = 0;
  for (size_t i = 0; i < 2; ++i)
    to_end = std::max(
        to_end, (last.constraints.handles[i].target - state.constraints.handles[i].target).norm());
  EXPECT_GT(moved, 1.0);
  EXPECT_GT(to_end, 1.0);
}

TEST_F(RenderSaved, RunIterationDrawsThatFrameAndTheLastByDefault) {
  const auto by_run = render("--run " + run_ + " --iteration 10" + kPicture, "render_saved_run10");
  const auto by_frame = render("--frame " + frame(10) + kPicture, "render_saved_frame10");
  const auto last_by_run = render("--run " + run_ + kPicture, "render_saved_run_last");
  const auto last_by_frame = render("--frame " + frame(25) + kPicture, "render_saved_frame25");
  const auto other = render("--frame " + frame(20) + kPicture, "render_saved_frame20");
  for (const auto* r : {&by_run, &by_frame, &last_by_run, &last_by_frame, &other}) {
    ASSERT_EQ(r->first.code, 0) << r->first.err;
    EXPECT_NE(r->first.out.find("wrote " + r->second), std::string::npos) << r->first.out;
  }
  EXPECT_EQ(test::differing_pixels(test::read_png(by_run.second), test::read_png(by_frame.second)),
            0);
  EXPECT_EQ(test::differing_pixels(test::read_png(last_by_run.second),
                                   test::read_png(last_by_frame.second)),
            0);
  // Other iterations give other pictures: the comparisons above can fail.
  EXPECT_GT(test::differing_pixels(test::read_png(by_frame.second), test::read_png(other.second)),
            1000);
  EXPECT_GT(
      test::differing_pixels(test::read_png(last_by_frame.second), test::read_png(other.second)),
      100);
}

// A frame without its run.json (as the studio records them) is drawn on the model the command line
// names; without the run's handles the pictures agree, captions left out.
TEST_F(RenderSaved, AGivenPatternDrawsAFrameWithoutItsRecord) {
  const std::string bare = copy_of_run("render_saved_bare", {"run.json"});
  const std::string picture =
      " --overlay dog-residual,crease-curves --view 3d --size 480x300 --caption ''";
  const auto given =
      render("'" + kArcs + "' --res 21x21 --frame " + bare + "/frame_0020.vtu" + picture,
             "render_saved_given");
  const auto recorded = render("--frame " + frame(20) + picture, "render_saved_recorded");
  ASSERT_EQ(given.first.code, 0) << given.first.err;
  ASSERT_EQ(recorded.first.code, 0) << recorded.first.err;
  EXPECT_EQ(test::differing_pixels(test::read_png(given.second), test::read_png(recorded.second)),
            0);
}

TEST_F(RenderSaved, BadInputIsRefusedNamingTheFile) {
  expect_refused(render("--frame " + run_ + "/frame_0015.vtu", "render_saved_missing"), 1,
                 {run_ + "/frame_0015.vtu: no such file"});

  const std::string junk =
      test::write_file(test::temp_dir("render_saved_junk"), "frame_0010.vtu", "not a VTK file\n");
  expect_refused(render("--frame " + junk, "render_saved_junk_out"), 1,
                 {junk + ": not a readable VTK unstructured grid"});

  expect_refused(render("'" + test::dataset("one_curve.svg") + "' --res 21x15 --frame " + frame(10),
                        "render_saved_other"),
                 1, {frame(10) + " is not a frame of ", "one_curve.svg at 21x15", "553 vertices"});

  // The same mesh drawn from another rest state: one vertex moved in the frame's rest positions.
  const std::string moved = copy_of_run("render_saved_moved_rest", {});
  {
    auto grid = read_grid(moved + "/frame_0010.vtu");
    vtkDataArray* rest = grid->GetPointData()->GetArray("rest_position");
    ASSERT_NE(rest, nullptr);
    rest->SetComponent(7, 0, rest->GetComponent(7, 0) + 0.25);
    auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    writer->SetFileName((moved + "/frame_0010.vtu").c_str());
    writer->SetInputData(grid);
    ASSERT_EQ(writer->Write(), 1);
  }
  expect_refused(
      render("--frame " + moved + "/frame_0010.vtu", "render_saved_moved_out"), 1,
      {moved + "/frame_0010.vtu is not a frame of", "vertex 7", moved + "/run.json records it"});

  expect_refused(render("--run " + run_ + " --iteration 15", "render_saved_iteration"), 1,
                 {run_ + "/frames.pvd: no frame of iteration 15", "0 to 20 every 10, and 25"});
  const std::string no_record = copy_of_run("render_saved_no_record", {"run.json"});
  expect_refused(render("--run " + no_record, "render_saved_no_record_out"), 1,
                 {no_record + ": no run.json", "PATTERN"});
  expect_refused(render("--frame " + no_record + "/frame_0010.vtu", "render_saved_no_record_frame"),
                 1, {no_record + "/frame_0010.vtu: no run.json beside it"});
  expect_refused(render("--run " + run_ + "/none", "render_saved_no_dir"), 1,
                 {run_ + "/none: no such directory"});

  // A record whose pattern has gone: refused, unless the pattern is given.
  const std::string moved_pattern = copy_of_run("render_saved_gone", {});
  nlohmann::json record = nlohmann::json::parse(test::slurp(moved_pattern + "/run.json"));
  record["pattern"] = record["pattern_path"] = "/no/such/pattern.svg";
  std::ofstream(moved_pattern + "/run.json") << record.dump(2);
  expect_refused(render("--run " + moved_pattern, "render_saved_gone_out"), 1,
                 {moved_pattern + "/run.json", "/no/such/pattern.svg", "PATTERN"});
  EXPECT_EQ(render("'" + kArcs + "' --run " + moved_pattern + " --size 160x100",
                   "render_saved_gone_given")
                .first.code,
            0);
}

TEST_F(RenderSaved, OptionsThatCannotWorkTogetherAreUsageErrors) {
  for (const std::string& args : std::vector<std::string>{
           "--frame " + frame(10) + " --iters 5", "--frame " + frame(10) + " --run " + run_,
           "--iteration 10", "", "--frame " + frame(10) + " --scenario fold"}) {
    const auto r = render(args, "render_saved_usage");
    expect_refused(r, 2, {});
  }
}

}  // namespace
}  // namespace sdog
