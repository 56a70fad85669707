// The commands without an X display (DISPLAY removed from their environment, so that no Xvfb the
// tests may run under is reachable): those whose results are files need none, sdog compare leaves
// out its plots and says so once, sdog render refuses with one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/app/csv.h"
#include "tests/app/run_sdog.h"

namespace sdog {
namespace {

namespace fs = std::filesystem;

const std::string kNoDisplay = "env -u DISPLAY";
const std::string kPattern = test::dataset("one_curve.svg");

int occurrences(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

bool has_png(const std::string& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".png") return true;
  return false;
}

TEST(NoDisplay, CompareWritesItsTablesAndSaysOnceThatThePlotsAreSkipped) {
  const std::string dir = test::temp_dir("headless_compare") + "/out";
  const auto r = test::run_sdog(
      "compare --pattern '" + kPattern +
          "' --res 15x11 --modes standard,subsolvers --iters 4 --hold 1 --out " + dir,
      kNoDisplay);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(occurrences(r.out + r.err, "plots are skipped"), 1) << r.out << r.err;
  const std::string notice = r.err.substr(r.err.find("sdog compare: no X display"));
  EXPECT_NE(notice.substr(0, notice.find('\n')).find("xvfb-run -a"), std::string::npos) << r.err;
  EXPECT_FALSE(has_png(dir)) << "plots drawn without a display in " << dir;

  const test::Csv csv = test::read_csv(dir + "/compare.csv");
  ASSERT_EQ(csv.rows.size(), 2u);
  const auto json =
      nlohmann::json::parse(test::slurp(dir + "/compare.json"));  // throws if not JSON
  const auto& table = json.at("table");
  ASSERT_EQ(table.size(), 2u);
  const char* modes[] = {"standard", "subsolvers"};
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(table[i].at("mode"), modes[i]);
    EXPECT_EQ(csv.rows[i].at(csv.column("mode")), modes[i]);
    EXPECT_EQ(table[i].at("pattern"), "one_curve");
    EXPECT_EQ(table[i].at("res"), "15x11");
    EXPECT_EQ(table[i].at("status"), "completed");
    EXPECT_EQ(table[i].at("iterations"), 5);
  }
  EXPECT_NE(r.out.find("compare.json}"), std::string::npos) << r.out;
}

TEST(NoDisplay, MeshRunAndBenchNeedNone) {
  const std::string dir = test::temp_dir("headless_files");
  const auto mesh =
      test::run_sdog("mesh '" + kPattern + "' --res 15x11 --out " + dir + "/mesh", kNoDisplay);
  ASSERT_EQ(mesh.code, 0) << mesh.err;
  EXPECT_TRUE(fs::exists(dir + "/mesh/fine.vtu"));
  const auto run = test::run_sdog(
      "run '" + kPattern + "' --res 15x11 --iters 4 --hold 1 -q --frames-every 2 --out " + dir +
          "/run",
      kNoDisplay);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir + "/run/run.json"));
  EXPECT_TRUE(fs::exists(dir + "/run/frame_0005.vtu"));
  const auto bench =
      test::run_sdog("bench --pattern '" + kPattern + "' --res 15x11 --iters 12 --repeat 1 --csv " +
                         dir + "/bench.csv",
                     kNoDisplay);
  ASSERT_EQ(bench.code, 0) << bench.err;
  EXPECT_TRUE(fs::exists(dir + "/bench.csv"));
  for (const auto* r : {&mesh, &run, &bench})
    EXPECT_EQ(r->err.find("display"), std::string::npos) << r->err;
}

TEST(NoDisplay, RenderRefusesWithOneLineAndWritesNothing) {
  const std::string dir = test::temp_dir("headless_render");
  const auto r =
      test::run_sdog("render '" + kPattern + "' --res 15x11 --out " + dir + "/x.png", kNoDisplay);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("xvfb-run"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
}  // namespace sdog
