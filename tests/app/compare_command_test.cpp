// `sdog compare` as a user runs it: the table (columns, ratios to standard recomputed from the
// other columns), the long-format series, compare.json, the plots, and the errors before the work.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/app/csv.h"
#include "tests/app/run_sdog.h"
#include "tests/ui/vis/image_compare.h"

namespace sdog {
namespace {

namespace fs = std::filesystem;
using test::Csv;
using test::read_csv;

const std::string kPattern = test::dataset("one_curve.svg");
const std::string kSmallCompare =
    "compare --pattern '" + kPattern +
    "' --res 15x11 --modes standard,subsolvers --iters 6 --hold 2 --plot-size 640x400";

#define SDOG_REQUIRE_DISPLAY()                                                               \
  do {                                                                                       \
    const char* display = std::getenv("DISPLAY");                                            \
    if (!display || !*display) GTEST_SKIP() << "no X display: run the tests under xvfb-run"; \
  } while (0)

TEST(CompareCommand, WritesTheTableSeriesJsonAndPlots) {
  SDOG_REQUIRE_DISPLAY();
  const std::string dir = test::temp_dir("compare") + "/out";
  const auto r = test::run_sdog(kSmallCompare + " --out " + dir);
  ASSERT_EQ(r.code, 0) << r.err;

  const Csv csv = read_csv(dir + "/compare.csv");
  const std::vector<std::string> columns = {"pattern",
                                            "res",
                                            "mode",
                                            "vertices",
                                            "dof",
                                            "iterations",
                                            "final_objective",
                                            "objective_ratio",
                                            "median_ms",
                                            "speedup",
                                            "total_s",
                                            "total_speedup",
                                            "speedup_paired",
                                            "dog_max",
                                            "dog_max_run",
                                            "stitch_gap_max",
                                            "folded",
                                            "status"};
  ASSERT_GE(csv.header.size(), columns.size());
  for (size_t i = 0; i < columns.size(); ++i)
    EXPECT_EQ(csv.header[i], columns[i]) << "column " << i;
  ASSERT_EQ(csv.rows.size(), 2u);
  auto field = [&](int row, const std::string& name) { return csv.rows[row].at(csv.column(name)); };
  auto number = [&](int row, const std::string& name) { return std::stod(field(row, name)); };
  EXPECT_EQ(field(0, "mode"), "standard");
  EXPECT_EQ(field(1, "mode"), "subsolvers");
  for (int row : {0, 1}) {
    EXPECT_EQ(field(row, "pattern"), "one_curve");
    EXPECT_EQ(field(row, "res"), "15x11");
    EXPECT_EQ(field(row, "status"), "completed");
    EXPECT_EQ(std::stoi(field(row, "dof")), 3 * std::stoi(field(row, "vertices")));
    EXPECT_EQ(std::stoi(field(row, "iterations")), 8);
    EXPECT_GT(number(row, "final_objective"), 0);
    EXPECT_GT(number(row, "median_ms"), 0);
    EXPECT_GE(number(row, "dog_max_run"), number(row, "dog_max"));
    EXPECT_TRUE(field(row, "folded") == "0" || field(row, "folded") == "1");
  }
  // The patterned sheet has more vertices than the grid (copies along the crease).
  EXPECT_GT(std::stoi(field(0, "vertices")), 15 * 11);
  EXPECT_EQ(field(0, "vertices"), field(1, "vertices"));
  EXPECT_DOUBLE_EQ(number(0, "objective_ratio"), 1.0);
  EXPECT_DOUBLE_EQ(number(0, "speedup"), 1.0);
  const double ratio = number(1, "final_objective") / number(0, "final_objective");
  EXPECT_NEAR(number(1, "objective_ratio"), ratio, 1e-6 * ratio);
  const double speedup = number(0, "median_ms") / number(1, "median_ms");
  EXPECT_NEAR(number(1, "speedup"), speedup, 2e-3 * speedup);  // median_ms has 4 digits
  // One round: the paired speedup is that round's ratio, the speedup itself.
  EXPECT_NEAR(number(1, "speedup_paired"), speedup, 2e-3 * speedup);

  // series.csv: every iteration of both modes, long format; its last objective is the table's.
  const Csv series = read_csv(dir + "/series.csv");
  EXPECT_EQ(series.header,
            (std::vector<std::string>{"pattern", "res", "mode", "iteration", "objective", "ms",
                                      "dog_max", "stitch_gap_max"}));
  ASSERT_EQ(series.rows.size(), 16u);
  for (int k = 0; k < 16; ++k) {
    EXPECT_EQ(series.rows[k][2], k < 8 ? "standard" : "subsolvers");
    EXPECT_EQ(std::stoi(series.rows[k][3]), k % 8 + 1);
  }
  EXPECT_EQ(series.rows[7][4], field(0, "final_objective"));
  EXPECT_EQ(series.rows[15][4], field(1, "final_objective"));
  // total_s: the whole run, every iteration's time summed (the series rounds each to 4 digits).
  for (int row : {0, 1}) {
    double sum_ms = 0;
    for (int k = 8 * row; k < 8 * row + 8; ++k) sum_ms += std::stod(series.rows[k][5]);
    EXPECT_NEAR(number(row, "total_s"), sum_ms / 1000, 2e-3 * sum_ms / 1000) << "row " << row;
    EXPECT_GT(number(row, "total_s") * 1000, number(row, "median_ms"));
  }
  EXPECT_DOUBLE_EQ(number(0, "total_speedup"), 1.0);
  const double total_speedup = number(0, "total_s") / number(1, "total_s");
  EXPECT_NEAR(number(1, "total_speedup"), total_speedup,
              2e-3 * total_speedup);  // total_s has 4 digits

  // compare.json: command line, configuration, versions and the same table.
  const auto j = nlohmann::json::parse(test::slurp(dir + "/compare.json"));
  EXPECT_NE(j.at("command_line").get<std::string>().find("--modes standard,subsolvers"),
            std::string::npos);
  EXPECT_EQ(j.at("config").at("iterations"), 6);
  EXPECT_EQ(j.at("config").at("hold"), 2);
  EXPECT_TRUE(j.at("software").contains("vtk"));
  ASSERT_EQ(j.at("table").size(), 2u);
  EXPECT_EQ(j.at("table")[1].at("mode"), "subsolvers");
  EXPECT_NEAR(j.at("table")[1].at("objective_ratio").get<double>(), ratio, 1e-6 * ratio);

  // The two plots of the case, at the requested size; no scaling plot for a single resolution.
  for (const char* name : {"objective_one_curve_15x11.png", "time_one_curve_15x11.png"}) {
    ASSERT_TRUE(fs::exists(dir + "/" + name)) << name;
    auto img = test::read_png(dir + "/" + name);
    int dims[3];
    img->GetDimensions(dims);
    EXPECT_EQ(dims[0], 640) << name;
    EXPECT_EQ(dims[1], 400) << name;
  }
  EXPECT_FALSE(fs::exists(dir + "/ms_per_dof_one_curve.png"));

  // The table on stdout and where the results are.
  EXPECT_NE(r.out.find("objective_ratio"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("subsolvers"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(dir), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("case 2/2"), std::string::npos) << r.err;
}

// --config: the same JSON as sdog run's for every run (iteration counts, weights, mode options);
// the command line's --iters wins, and switches are refused (every mode runs on its own).
TEST(CompareCommand, ConfigFileSetsEveryRunAndTheCommandLineWins) {
  const std::string dir = test::temp_dir("compare_config");
  const std::string config = test::write_file(
      dir, "c.json", R"({"iterations": 3, "hold": 1, "twolevel": {"fold_sharpness": 100}})");
  const std::string base = "compare --pattern '" + kPattern +
                           "' --res 15x11 --modes standard --plot-size 640x400 --config " + config;
  const auto r = test::run_sdog(base + " --out " + dir + "/a");
  ASSERT_EQ(r.code, 0) << r.err;
  const Csv a = read_csv(dir + "/a/compare.csv");
  ASSERT_EQ(a.rows.size(), 1u);
  EXPECT_EQ(std::stoi(a.rows[0].at(a.column("iterations"))), 4);
  const nlohmann::json json = nlohmann::json::parse(test::slurp(dir + "/a/compare.json"));
  EXPECT_EQ(json.at("config").at("twolevel").at("fold_sharpness").get<double>(), 100);

  const auto b = test::run_sdog(base + " --iters 5 --out " + dir + "/b");
  ASSERT_EQ(b.code, 0) << b.err;
  const Csv bc = read_csv(dir + "/b/compare.csv");
  EXPECT_EQ(std::stoi(bc.rows.at(0).at(bc.column("iterations"))), 6);

  const std::string switches =
      test::write_file(dir, "s.json", R"({"switches": [{"iteration": 2, "mode": "subsolvers"}]})");
  const auto c =
      test::run_sdog("compare --pattern '" + kPattern + "' --res 15x11 --modes standard --config " +
                     switches + " --out " + dir + "/c");
  EXPECT_EQ(c.code, 2) << c.err;
  EXPECT_EQ(test::count_lines(c.err), 1) << c.err;
  EXPECT_NE(c.err.find("$.switches"), std::string::npos) << c.err;
  EXPECT_FALSE(fs::exists(dir + "/c"));
}

TEST(CompareCommand, UnknownModeIsAUsageErrorNamingIt) {
  const std::string dir = test::temp_dir("compare_mode");
  const auto r = test::run_sdog("compare --pattern '" + kPattern +
                                "' --res 15x11 --modes standard,warp --out " + dir + "/out");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("warp"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

TEST(CompareCommand, UnknownScenarioIsAUsageError) {
  const auto r = test::run_sdog(kSmallCompare + " --scenario twist --out " +
                                test::temp_dir("compare_scenario"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("twist"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("corners"), std::string::npos) << r.err;
}

TEST(CompareCommand, UnwritableOutputFailsBeforeTheWork) {
  const auto r = test::expect_unwritable_output_fails(kSmallCompare, "compare_unwritable");
  EXPECT_EQ(r.out, "");  // not even the table header: nothing ran
}

}  // namespace
}  // namespace sdog
