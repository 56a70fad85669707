// sdog bench as a user runs it: the table as CSV, an unwritable CSV refused before the work, the
// pace benchmark and the fold benchmark.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/app/csv.h"
#include "tests/app/run_sdog.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

using test::Csv;
using test::read_csv;

const std::string kPattern = test::dataset("one_curve.svg");

TEST(BenchCommand, UnwritableCsvFailsBeforeTheWork) {
  const std::string dir = test::temp_dir("bench_unwritable");
  test::write_file(dir, "file", "x");
  auto r = test::run_sdog("bench --pattern '" + kPattern +
                          "' --res 15x11 --iters 12 --repeat 1 --csv " + dir + "/file/bench.csv");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(dir + "/file"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("15x11"), std::string::npos) << "benchmarked before failing:\n" << r.out;
  // A directory that passes access() for root but takes no files (/proc): refused before the work
  // too.
  r = test::run_sdog("bench --pattern '" + kPattern +
                     "' --res 15x11 --iters 12 --repeat 1 --csv /proc/bench.csv");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("/proc: the output directory is not writable"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("15x11"), std::string::npos) << "benchmarked before failing:\n" << r.out;
}

TEST(BenchCommand, WritesTheTableAsCsv) {
  const std::string dir = test::temp_dir("bench");
  const auto r =
      test::run_sdog("bench --pattern '" + kPattern +
                     "' --res 15x11 --modes standard,subsolvers --iters 12 --repeat 2 --csv " +
                     dir + "/bench.csv");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("median_ms"), std::string::npos) << r.out;
  const Csv csv = read_csv(dir + "/bench.csv");
  for (const char* name : {"pattern", "res", "mode", "vertices", "dof", "median_ms", "ms_per_dof",
                           "sqp_steps", "factor_ms", "final_objective", "dog_max"})
    EXPECT_GE(csv.column(name), 0) << name;
  ASSERT_EQ(csv.rows.size(), 2u);
  const auto& row = csv.rows[0];
  // The speedups over the standard run: 1 for the standard itself; for the other mode the ratio of
  // the medians (4 digits each in the CSV).
  EXPECT_EQ(csv.rows[1][csv.column("mode")], "subsolvers");
  EXPECT_EQ(std::stod(row[csv.column("speedup")]), 1.0);
  EXPECT_EQ(std::stod(row[csv.column("speedup_paired")]), 1.0);
  const double speedup =
      std::stod(row[csv.column("median_ms")]) / std::stod(csv.rows[1][csv.column("median_ms")]);
  EXPECT_NEAR(std::stod(csv.rows[1][csv.column("speedup")]), speedup, 2e-3 * speedup);
  EXPECT_GT(std::stod(csv.rows[1][csv.column("speedup_paired")]), 0);
  EXPECT_EQ(csv.rows[1][csv.column("repeats")], "2");
  EXPECT_EQ(row[csv.column("res")], "15x11");
  EXPECT_EQ(row[csv.column("mode")], "standard");
  const int vertices = std::stoi(row[csv.column("vertices")]);
  EXPECT_EQ(std::stoi(row[csv.column("dof")]), 3 * vertices);
  EXPECT_GT(std::stod(row[csv.column("median_ms")]), 0);
  // Both columns carry 4 significant digits: each may be off by half a unit in the fourth.
  const double ms_per_dof = std::stod(row[csv.column("ms_per_dof")]);
  EXPECT_NEAR(ms_per_dof, std::stod(row[csv.column("median_ms")]) / (3 * vertices),
              1e-3 * ms_per_dof);
  EXPECT_LT(std::stod(row[csv.column("dog_max")]), 1e-4);
}

// The pace benchmark on a bundled pattern: the slow drag and the target set at once both end
// converged, folded, on the constraints, and in the same fold (objectives within 2%).
TEST(BenchCommand, PaceRunsEveryKToAConvergedShape) {
  const std::string dir = test::temp_dir("bench_pace");
  const auto r = test::run_sdog("bench --pace --pattern '" + test::dataset("four_corner_arcs.svg") +
                                "' --res 21x21 --ks 250,1 --csv " + dir + "/pace.csv");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("shape_s"), std::string::npos) << r.out;
  const Csv csv = read_csv(dir + "/pace.csv");
  ASSERT_EQ(csv.rows.size(), 2u);
  for (const char* name : {"K", "objective", "folded", "dog_max", "stitch_gap", "handle_distance",
                           "shape_s", "iterations", "failure"})
    ASSERT_GE(csv.column(name), 0) << name;
  double best = 1e300;
  for (const auto& row : csv.rows) best = std::min(best, std::stod(row[csv.column("objective")]));
  for (const auto& row : csv.rows) {
    const std::string k = row[csv.column("K")];
    const size_t failure = static_cast<size_t>(csv.column("failure"));
    EXPECT_TRUE(failure >= row.size() || row[failure].empty()) << "K = " << k;
    EXPECT_EQ(row[csv.column("folded")], "1") << "K = " << k;
    EXPECT_LE(std::stod(row[csv.column("dog_max")]), 1e-6) << "K = " << k;
    EXPECT_LE(std::stod(row[csv.column("stitch_gap")]), 1e-6) << "K = " << k;
    EXPECT_LT(std::stod(row[csv.column("handle_distance")]), 0.02) << "K = " << k;
    EXPECT_GT(std::stod(row[csv.column("shape_s")]), 0)
        << "K = " << k << ": no converged iteration";
    EXPECT_LE(std::stod(row[csv.column("objective")]), 1.02 * best) << "K = " << k;
  }
  // The held iterations stop at convergence: far fewer than the 200 allowed.
  EXPECT_LT(std::stoi(csv.rows[1][csv.column("iterations")]), 100);
}

// --config gives the pace runs solver settings: without settling the drag costs fewer
// factorisations than with it (the straight fold is not computed). The timing benchmark refuses it.
TEST(BenchCommand, PaceTakesSolverSettingsFromAConfiguration) {
  const std::string dir = test::temp_dir("bench_pace_config");
  const std::string off_json =
      test::write_file(dir, "off.json", R"({"solver": {"settle": false}})");
  const std::string pace =
      "bench --pace --pattern '" + test::dataset("four_corner_arcs.svg") + "' --res 21x21 --ks 50";
  const auto on = test::run_sdog(pace + " --csv " + dir + "/on.csv");
  const auto off = test::run_sdog(pace + " --config " + off_json + " --csv " + dir + "/off.csv");
  ASSERT_EQ(on.code, 0) << on.err;
  ASSERT_EQ(off.code, 0) << off.err;
  const Csv with = read_csv(dir + "/on.csv"), without = read_csv(dir + "/off.csv");
  ASSERT_EQ(with.rows.size(), 1u);
  ASSERT_EQ(without.rows.size(), 1u);
  EXPECT_LT(std::stoi(without.rows[0][without.column("facts")]),
            std::stoi(with.rows[0][with.column("facts")]));
  const auto timing = test::run_sdog("bench --pattern '" + test::dataset("four_corner_arcs.svg") +
                                     "' --res 21x21 --config " + off_json);
  EXPECT_EQ(timing.code, 2);
  EXPECT_NE(timing.err.find("--config: only with --pace"), std::string::npos) << timing.err;
}

// The fold benchmark on the curved pleats: every run converges on the constraints with its fold
// sites bent the drawn way, and the paper keeps its lengths (pleats along parallel curves fold
// without stretching).
TEST(BenchCommand, FoldReportsDirectionResidualsAndTheStrainOfThePaper) {
  const std::string dir = test::temp_dir("bench_fold");
  const auto r = test::run_sdog("bench --fold --pattern '" + test::dataset("curved_pleats.svg") +
                                "' --res 21x21 --angles 30 90 --csv " + dir + "/fold.csv");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("strain"), std::string::npos) << r.out;
  const Csv csv = read_csv(dir + "/fold.csv");
  ASSERT_EQ(csv.rows.size(), 2u);
  for (const auto& row : csv.rows) {
    const std::string angle = row[csv.column("angle")];
    EXPECT_EQ(row[csv.column("converged")], "1") << angle;
    EXPECT_GT(std::stod(row[csv.column("shape_s")]), 0) << angle;
    EXPECT_GE(std::stod(row[csv.column("agreement")]), 0.95) << angle;
    EXPECT_GT(std::stoi(row[csv.column("bent")]), 0) << angle;
    EXPECT_LE(std::stod(row[csv.column("dog_max")]), 1e-6) << angle;
    EXPECT_LT(std::stod(row[csv.column("sheet_strain")]), 0.02) << angle;
  }
}

}  // namespace
}  // namespace sdog
