// `sdog run` and `sdog bench` as a user runs them: the files a run writes (run.csv, run.json,
// frames.pvd and its .vtu frames read back with VTK's XML readers), configuration errors with
// their JSON path, thread-count independence, and the benchmark table.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "tests/app/csv.h"
#include "tests/app/run_sdog.h"

namespace sdog {
namespace {

namespace fs = std::filesystem;
using test::Csv;
using test::read_csv;

const std::string kPattern = test::dataset("one_curve.svg");
const std::string kSmallRun = "run '" + kPattern + "' --res 21x15 --iters 20 --hold 5 -q";

TEST(RunCommand, WritesTheLogRunJsonAndFrames) {
  const std::string dir = test::temp_dir("run_files") + "/out";
  const auto r = test::run_sdog(kSmallRun + " --frames-every 10 --out " + dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("25 iterations of standard (corners)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("DOG max"), std::string::npos) << r.out;

  // run.csv: the issue's columns, in its order, one row per iteration, finite numbers.
  const Csv csv = read_csv(dir + "/run.csv");
  const std::vector<std::string> required = {"iteration",
                                             "t",
                                             "objective",
                                             "bending",
                                             "isometry",
                                             "positions",
                                             "edge_points",
                                             "stitching",
                                             "angles",
                                             "fold_bias",
                                             "objective_final_targets",
                                             "dog_max",
                                             "dog_l2",
                                             "stitch_gap_max",
                                             "edge_strain_max",
                                             "sheet_strain_max",
                                             "sqp_steps",
                                             "step_length",
                                             "fold_retries",
                                             "folded",
                                             "iteration_ms",
                                             "factor_ms"};
  int previous = -1;
  for (const auto& name : required) {
    const int c = csv.column(name);
    ASSERT_GE(c, 0) << "column " << name << " missing";
    EXPECT_GT(c, previous) << "column " << name << " out of order";
    previous = c;
  }
  ASSERT_EQ(csv.rows.size(), 25u);
  for (size_t i = 0; i < csv.rows.size(); ++i) {
    ASSERT_EQ(csv.rows[i].size(), csv.header.size()) << "row " << i;
    EXPECT_EQ(std::stoi(csv.rows[i][csv.column("iteration")]), static_cast<int>(i) + 1);
    for (size_t c = 0; c < csv.header.size(); ++c)
      if (csv.header[c] == "mode")
        EXPECT_EQ(csv.rows[i][c], "standard");
      else if (csv.header[c] == "settling")
        EXPECT_TRUE(csv.rows[i][c] == "" || csv.rows[i][c] == "running" ||
                    csv.rows[i][c] == "kept" || csv.rows[i][c] == "replaced")
            << csv.rows[i][c];
      else if (csv.header[c] == "direction_agreement" || csv.header[c] == "angle_error")
        EXPECT_EQ(csv.rows[i][c], "") << csv.header[c] << ": the corners scenario targets no angle";
      else
        EXPECT_TRUE(std::isfinite(std::stod(csv.rows[i][c])))
            << csv.header[c] << " " << csv.rows[i][c];
    EXPECT_LT(std::stod(csv.rows[i][csv.column("dog_max")]), 1e-4);
  }
  EXPECT_DOUBLE_EQ(std::stod(csv.rows.back()[csv.column("t")]), 1.0);
  EXPECT_DOUBLE_EQ(std::stod(csv.rows[9][csv.column("t")]), 0.5);

  // pattern.fold: the pattern as read, a FOLD crease pattern.
  const auto fold = nlohmann::json::parse(test::slurp(dir + "/pattern.fold"));
  EXPECT_EQ(fold.at("frame_classes"), nlohmann::json::array({"creasePattern"}));
  EXPECT_EQ(fold.at("edges_vertices").size(), fold.at("edges_assignment").size());

  // run.json: parameters, versions, totals, the final state.
  const auto j = nlohmann::json::parse(test::slurp(dir + "/run.json"));
  EXPECT_EQ(j.at("status"), "completed");
  EXPECT_EQ(j.at("mode"), "standard");
  EXPECT_EQ(j.at("resolution").at("fine"), "21x15");
  EXPECT_EQ(j.at("config").at("iterations"), 20);
  EXPECT_EQ(j.at("config").at("hold"), 5);
  EXPECT_EQ(j.at("config").at("weights").at("stitching"), 10);
  EXPECT_TRUE(j.at("config").at("solver").contains("kkt_tolerance"));
  EXPECT_TRUE(j.at("software").contains("eigen"));
  EXPECT_EQ(j.at("totals").at("iterations"), 25);
  const double objective = j.at("final").at("objective").get<double>();
  EXPECT_NEAR(objective, std::stod(csv.rows.back()[csv.column("objective")]), 1e-9 * objective);

  // frames.pvd through VTK's XML parser; every listed frame through the .vtu reader.
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  const std::string pvd = dir + "/frames.pvd";
  parser->SetFileName(pvd.c_str());
  ASSERT_EQ(parser->Parse(), 1);
  vtkXMLDataElement* root = parser->GetRootElement();
  ASSERT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  ASSERT_NE(collection, nullptr);
  std::vector<int> steps;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    steps.push_back(std::atoi(e->GetAttribute("timestep")));
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    const std::string file = dir + "/" + e->GetAttribute("file");
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    ASSERT_GT(grid->GetNumberOfPoints(), 0) << file;
    ASSERT_GT(grid->GetNumberOfCells(), 0) << file;
    for (const char* name :
         {"dog_residual", "bending", "patch", "vertex_type", "vertex_class", "position_residual"})
      EXPECT_NE(grid->GetPointData()->GetArray(name), nullptr) << file << ": point array " << name;
    vtkDataArray* strain = grid->GetCellData()->GetArray("edge_strain");
    ASSERT_NE(strain, nullptr) << file;
    vtkDataArray* residual = grid->GetPointData()->GetArray("dog_residual");
    ASSERT_NE(residual, nullptr);
    if (steps.back() > 0) {
      EXPECT_LT(residual->GetRange()[1], 1e-4) << file;
    }
  }
  EXPECT_EQ(steps, (std::vector<int>{0, 10, 20, 25}));
  EXPECT_FALSE(fs::exists(dir + "/patches.csv")) << "the standard mode has no patch solves";
}

// patches.csv of a patch mode: one row per patch and iteration, a timeline of the TBB workers.
std::string blas_of_run(const std::string& prefix, const std::string& name) {
  const std::string dir = test::temp_dir(name) + "/out";
  const auto r = test::run_sdog(
      "run '" + kPattern + "' --res 11x11 --iters 1 --hold 0 -q --frames-every 0 --out " + dir,
      prefix);
  EXPECT_EQ(r.code, 0) << r.err;
  const auto json = nlohmann::json::parse(test::slurp(dir + "/run.json"));
  return json["software"]["blas"].get<std::string>();
}

TEST(RunCommand, RunsOpenBlasAvx2KernelsWhereTheCpuHasThemUnlessToldOtherwise) {
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma"))
    GTEST_SKIP() << "no AVX2 and FMA";
  EXPECT_NE(blas_of_run("env -u OPENBLAS_CORETYPE", "blas_default").find("Haswell"),
            std::string::npos);
  EXPECT_NE(blas_of_run("env OPENBLAS_CORETYPE=Prescott", "blas_prescott").find("Prescott"),
            std::string::npos);
}

TEST(RunCommand, PatchModesWriteThePerPatchTimeline) {
  if (std::thread::hardware_concurrency() < 2)
    GTEST_SKIP() << "one core: no parallel patch solves to see";
  const std::string dir = test::temp_dir("run_patches") + "/out";
  const auto r =
      test::run_sdog("run '" + test::dataset("four_corner_arcs.svg") +
                     "' --res 21x21 --iters 20 --hold 5 -q --frames-every 0 --mode subsolvers "
                     "--threads 2 --out " +
                     dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("patches.csv"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(test::slurp(dir + "/run.json"));
  const int patches = j.at("mesh").at("patches").get<int>();
  ASSERT_GE(patches, 2);
  const Csv csv = read_csv(dir + "/patches.csv");
  const std::vector<std::string> columns = {
      "iteration", "mode",  "patch",          "thread",    "start_ms", "ms",
      "linear_ms", "steps", "factorizations", "objective", "dog_max",  "converged"};
  ASSERT_EQ(csv.header, columns);
  ASSERT_EQ(csv.rows.size(), static_cast<size_t>(25 * patches));
  std::set<int> threads;
  int overlapping = 0;  // iterations in which two patch solves ran at the same time
  for (int k = 0; k < 25; ++k) {
    std::vector<std::pair<double, double>> spans;
    for (int p = 0; p < patches; ++p) {
      const auto& row = csv.rows[static_cast<size_t>(k * patches + p)];
      EXPECT_EQ(std::stoi(row[0]), k + 1);
      EXPECT_EQ(row[1], "subsolvers");
      EXPECT_EQ(std::stoi(row[2]), p);
      const int thread = std::stoi(row[3]);
      EXPECT_GE(thread, 0);
      EXPECT_LT(thread, 2);
      threads.insert(thread);
      const double start = std::stod(row[4]), ms = std::stod(row[5]);
      EXPECT_GE(start, 0);
      EXPECT_GT(ms, 0);
      EXPECT_LE(std::stod(row[6]), ms * 1.001 + 0.01) << "linear solves within the patch's time";
      EXPECT_GE(std::stoi(row[7]), 0);  // a patch already at rest takes no step
      EXPECT_LT(std::stod(row[10]), 1e-4) << "iteration " << k + 1 << " patch " << p;
      EXPECT_EQ(row[11], "1");
      spans.emplace_back(start, start + ms);
    }
    bool overlap = false;
    for (size_t a = 0; a < spans.size(); ++a)
      for (size_t b = a + 1; b < spans.size(); ++b)
        overlap = overlap || (spans[a].first < spans[b].second && spans[b].first < spans[a].second);
    overlapping += overlap;
  }
  EXPECT_EQ(threads.size(), 2u) << "both workers ran patch solves";
  EXPECT_GT(overlapping, 0) << "patch solves overlapped in time in no iteration";
}

TEST(RunCommand, SameCsvWhateverTheThreadCount) {
  const std::string base = test::temp_dir("run_threads");
  ASSERT_EQ(test::run_sdog(kSmallRun + " --frames-every 0 --threads 1 --out " + base + "/a").code,
            0);
  ASSERT_EQ(test::run_sdog(kSmallRun + " --frames-every 0 --threads 2 --out " + base + "/b").code,
            0);
  const Csv a = read_csv(base + "/a/run.csv"), b = read_csv(base + "/b/run.csv");
  ASSERT_EQ(a.header, b.header);
  ASSERT_EQ(a.rows.size(), b.rows.size());
  // Every column but the three times.
  const int t1 = a.column("iteration_ms"), t2 = a.column("factor_ms"), t3 = a.column("elapsed_ms");
  ASSERT_GE(t3, 0);
  for (size_t i = 0; i < a.rows.size(); ++i)
    for (size_t c = 0; c < a.header.size(); ++c)
      if (static_cast<int>(c) != t1 && static_cast<int>(c) != t2 && static_cast<int>(c) != t3) {
        EXPECT_EQ(a.rows[i][c], b.rows[i][c]) << "row " << i << " column " << a.header[c];
      }
}

struct ConfigCase {
  std::string name, json;
  std::vector<std::string> mentions;
  friend void PrintTo(const ConfigCase& c, std::ostream* os) { *os << c.name; }
};

class BadConfig : public ::testing::TestWithParam<ConfigCase> {};

TEST_P(BadConfig, OneLineNamingTheJsonPathAndNoOutput) {
  const ConfigCase& c = GetParam();
  const std::string dir = test::temp_dir("config_" + c.name);
  const std::string config = test::write_file(dir, "c.json", c.json);
  const auto r = test::run_sdog(kSmallRun + " --config " + config + " --out " + dir + "/out");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("c.json"), std::string::npos) << r.err;
  for (const auto& m : c.mentions)
    EXPECT_NE(r.err.find(m), std::string::npos) << "'" << m << "' not in " << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadConfig,
    ::testing::Values(
        ConfigCase{"not_json", "{ iterations: 3", {"JSON"}},
        ConfigCase{"unknown_key",
                   R"({"solver": {"kkt_tolerence": 1e-3}})",
                   {"$.solver.kkt_tolerence", "unknown key"}},
        ConfigCase{"bad_type", R"({"iterations": "many"})", {"$.iterations"}},
        ConfigCase{"negative_weight", R"({"weights": {"bending": -1}})", {"bending"}},
        ConfigCase{"bad_vertex",
                   R"({"positions": [{"vertex": 99999, "move": [0, 0, 1]}]})",
                   {"$.positions[0]", "99999"}},
        ConfigCase{"bad_target",
                   R"({"positions": [{"vertex": 3, "end": [1, 2]}]})",
                   {"$.positions[0].end"}},
        ConfigCase{"bad_crease_point",
                   R"({"angles": [{"crease_point": 100000, "end": 30}]})",
                   {"$.angles[0]", "100000"}},
        ConfigCase{"bad_scenario", R"({"scenario": "twist"})", {"$.scenario", "twist"}},
        ConfigCase{"switch_outside_run",
                   R"({"switches": [{"iteration": 26, "mode": "subsolvers"}]})",
                   {"$.switches[0]", "iteration 26"}},
        ConfigCase{
            "switches_unordered",
            R"({"switches": [{"iteration": 9, "mode": "subsolvers"}, {"iteration": 4, "mode": "standard"}]})",
            {"$.switches[1]", "ascending"}},
        ConfigCase{"negative_standard_finish",
                   R"({"twolevel": {"standard_finish": -1}})",
                   {"$.twolevel.standard_finish"}},
        ConfigCase{"fractional_standard_finish",
                   R"({"twolevel": {"standard_finish": 2.5}})",
                   {"$.twolevel.standard_finish"}},
        ConfigCase{"finish_fold_bias_cap_below_1",
                   R"({"twolevel": {"finish_fold_bias_cap": 0.5}})",
                   {"$.twolevel.finish_fold_bias_cap", ">= 1"}},
        ConfigCase{"zero_fold_sharpness",
                   R"({"twolevel": {"fold_sharpness": 0}})",
                   {"$.twolevel.fold_sharpness"}},
        ConfigCase{"coarse_every_zero",
                   R"({"twolevel": {"coarse_every": 0}})",
                   {"$.twolevel.coarse_every"}},
        ConfigCase{"concurrent_coarse_not_boolean",
                   R"({"twolevel": {"concurrent_coarse": 1}})",
                   {"$.twolevel.concurrent_coarse"}},
        ConfigCase{"coarse_concurrent_coarse_not_boolean",
                   R"({"coarse": {"concurrent_coarse": "yes"}})",
                   {"$.coarse.concurrent_coarse"}}));

TEST(RunCommand, ConfigConstraintsDriveTheRun) {
  const std::string dir = test::temp_dir("config_good");
  // No scenario: one vertex lifted by 2 units, the opposite corner held; the log shows the lift.
  const std::string config = test::write_file(dir, "c.json", R"({
    "scenario": "none", "iterations": 10, "hold": 2,
    "positions": [{"vertex": 0, "move": [0, 0, 0]}, {"near": [1e9, 1e9], "move": [0, 0, 2]}],
    "solver": {"kkt_tolerance": 1e-4}
  })");
  const auto r = test::run_sdog("run '" + kPattern + "' --res 21x15 -q --frames-every 0 --config " +
                                config + " --out " + dir + "/out");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(test::slurp(dir + "/out/run.json"));
  EXPECT_EQ(j.at("scenario").at("position_constraints"), 2);
  EXPECT_EQ(j.at("config").at("solver").at("kkt_tolerance"), 1e-4);
  const Csv csv = read_csv(dir + "/out/run.csv");
  ASSERT_EQ(csv.rows.size(), 12u);
  EXPECT_GT(std::stod(csv.rows.back()[csv.column("bending")]), 0);
  EXPECT_LT(std::stod(csv.rows.back()[csv.column("positions")]), 0.1);
}

// A corner pulled far off the sheet stretches it (the targets are soft): the run says so, names
// the patch and the sense; the thesis drag of the same sheet stretches it less and gets no warning.
TEST(RunCommand, WarnsWhenTheSheetStretches) {
  const std::string dir = test::temp_dir("stretch");
  const std::string config = test::write_file(dir, "c.json", R"({
    "scenario": "none", "iterations": 5, "hold": 5,
    "positions": [{"vertex": 0, "move": [0, 0, 0]}, {"near": [1e9, 1e9], "move": [6, 6, 0]}]
  })");
  const auto r = test::run_sdog("run '" + kPattern + "' --res 21x15 -q --frames-every 0 --config " +
                                config + " --out " + dir + "/out");
  ASSERT_EQ(r.code, 0) << r.err;
  const Csv csv = read_csv(dir + "/out/run.csv");
  const double strain = std::stod(csv.rows.back()[csv.column("sheet_strain_max")]);
  EXPECT_GT(strain, 0.05);
  EXPECT_NE(r.err.find("warning: the sheet stretches: an edge of patch 0 is "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("% longer than drawn"), std::string::npos) << r.err;

  const auto drag = test::run_sdog(kSmallRun + " --frames-every 0 --out " + dir + "/drag");
  ASSERT_EQ(drag.code, 0) << drag.err;
  EXPECT_EQ(drag.err.find("stretches"), std::string::npos) << drag.err;
}

// The v pleat's creases end together inside the sheet: the run names that fold tip and both
// creases before it starts, and reports the fold sites next to it apart from the others.
TEST(RunCommand, AFoldTipIsNamedAndItsSitesCountedApart) {
  const std::string dir = test::temp_dir("fold_tip");
  const auto r = test::run_sdog(
      "run '" + test::dataset("v_pleat.fold") +
      "' --res 21x21 --scenario fold --iters 1 --hold 20 -q --frames-every 0 --out " + dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("creases 0 (" + test::dataset("v_pleat.fold") + ": edge 6) and 1 (" +
                       test::dataset("v_pleat.fold") + ": edge 22) end together"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("more sites within 6 grid edges of a fold tip"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(test::slurp(dir + "/run.json"));
  const auto& f = j.at("final").at("fold_angles");
  EXPECT_GT(f.at("fold_tip_sites").get<int>(), 0);
  EXPECT_GE(f.at("fold_tip_sites").get<int>(), f.at("fold_tip_sites_against").get<int>());
  EXPECT_GT(f.at("targeted_sites").get<int>(), 0);
}

// --switch: the run changes mode where asked; run.csv says which mode computed each iteration.
TEST(RunCommand, SwitchesModesDuringTheRun) {
  const std::string dir = test::temp_dir("run_switch");
  const auto r = test::run_sdog("run '" + kPattern +
                                "' --res 21x15 --iters 12 --hold 3 -q --frames-every 0 "
                                "--switch 5:subsolvers --switch 11:standard --out " +
                                dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("standard, subsolvers from iteration 5, standard from iteration 11"),
            std::string::npos)
      << r.out;
  const Csv csv = read_csv(dir + "/run.csv");
  ASSERT_EQ(csv.rows.size(), 15u);
  for (size_t i = 0; i < csv.rows.size(); ++i) {
    const int k = static_cast<int>(i) + 1;
    EXPECT_EQ(csv.rows[i][csv.column("mode")], k >= 5 && k < 11 ? "subsolvers" : "standard")
        << "iteration " << k;
    EXPECT_LT(std::stod(csv.rows[i][csv.column("dog_max")]), 1e-4) << "iteration " << k;
  }
  const auto j = nlohmann::json::parse(test::slurp(dir + "/run.json"));
  ASSERT_EQ(j.at("config").at("switches").size(), 2u);
  EXPECT_EQ(j.at("config").at("switches")[0].at("mode"), "subsolvers");
}

TEST(RunCommand, UsageErrorsExitWithTwo) {
  auto r = test::run_sdog(kSmallRun + " --mode warp");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("warp"), std::string::npos) << r.err;
  r = test::run_sdog(kSmallRun + " --preset warp");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--preset: warp"), std::string::npos) << r.err;
  r = test::run_sdog("run '" + test::dataset("diagonal_fold.svg") +
                     "' --res 21x21 -q --scenario fold");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("no fold sites"), std::string::npos) << r.err;
  r = test::run_sdog(kSmallRun + " --switch 5:warp");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--switch 5:warp: unknown mode 'warp'"), std::string::npos) << r.err;
  r = test::run_sdog(kSmallRun + " --switch five:subsolvers");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("ITERATION:MODE"), std::string::npos) << r.err;
  // A coarse mode needs the coarse mesh: refused before the run, not at the switch.
  r = test::run_sdog("run '" + kPattern +
                     "' --res 20x14 --fine-only --iters 20 --hold 5 -q --switch 5:twolevel");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("twolevel needs the coarse mesh"), std::string::npos) << r.err;
}

TEST(RunCommand, UnwritableOutputFailsBeforeTheWork) {
  test::expect_unwritable_output_fails(kSmallRun, "run_unwritable");
}

}  // namespace
}  // namespace sdog
