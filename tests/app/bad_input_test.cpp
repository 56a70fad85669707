// Bad input: one-line message naming the file, element and position; exit code 1 for bad input,
// 2 for usage errors; no crash and no partial output.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/app/run_sdog.h"

namespace sdog {
namespace {

const char* kCrease = R"(<path d="M 0 50 C 30 40, 60 60, 100 50" stroke="red" fill="none"/>)";

std::string svg(const std::string& body, const std::string& viewbox = "0 0 100 100") {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" + viewbox + "\">\n" + body +
         "\n</svg>\n";
}

struct BadCase {
  std::string name, text, res;
  int code;
  std::vector<std::string> mentions;  // parts the message must contain
  friend void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }
};

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, FailsWithOneClearLineAndNoOutput) {
  const BadCase& c = GetParam();
  const std::string dir = test::temp_dir("bad_" + c.name);
  const std::string path = test::write_file(dir, c.name + ".svg", c.text);
  const std::string out = dir + "/out";
  const auto r = test::run_sdog("mesh " + path + " --res " + c.res + " --out " + out);
  EXPECT_EQ(r.code, c.code) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  for (const auto& m : c.mentions)
    EXPECT_NE(r.err.find(m), std::string::npos) << "'" << m << "' not in: " << r.err;
  EXPECT_FALSE(std::filesystem::exists(out)) << "partial output left in " << out;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadInput,
    ::testing::Values(
        BadCase{"not_xml", "this is not XML <<<", "21x21", 1, {"not_xml.svg", "XML"}},
        BadCase{"no_svg_root",
                "<html><body/></html>",
                "21x21",
                1,
                {"no_svg_root.svg", "<html>", "<svg>"}},
        BadCase{"path_syntax",
                svg("<path id=\"c1\" d=\"M 0 50 L 100\" stroke=\"red\"/>"),
                "21x21",
                1,
                {"path_syntax.svg:2", "<path id=\"c1\">", "character"}},
        BadCase{"path_letter",
                svg("<path d=\"M 0 50 K 100 50\" stroke=\"red\"/>"),
                "21x21",
                1,
                {"path_letter.svg:2", "<path>", "'K'"}},
        BadCase{"nan",
                svg("<path d=\"M nan 50 L 100 50\" stroke=\"red\"/>"),
                "21x21",
                1,
                {"nan.svg:2", "<path>"}},
        BadCase{"infinite",
                svg("<line x1=\"0\" y1=\"50\" x2=\"1e999\" y2=\"50\" stroke=\"red\"/>"),
                "21x21",
                1,
                {"infinite.svg:2", "<line>", "finite"}},
        BadCase{"far_away",
                svg("<path d=\"M 0 50 L 50 1e60 L 100 50\" stroke=\"red\"/>"),
                "21x21",
                1,
                {"far_away.svg:2", "<path>", "sheet sizes away"}},
        BadCase{"bowtie",
                svg("<polygon points=\"0,0 100,100 100,0 0,100\" stroke=\"black\" fill=\"none\"/>"),
                "21x21",
                1,
                {"bowtie.svg:2", "<polygon>", "crosses itself"}},
        BadCase{"zero_area", svg(kCrease, "0 0 0 100"), "21x21", 1, {"zero_area.svg", "zero area"}},
        BadCase{"open_boundary",
                svg("<polyline points=\"0,0 100,0 100,100\" stroke=\"#000\" fill=\"none\"/>"),
                "21x21",
                1,
                {"open_boundary.svg:2", "<polyline>", "not closed"}},
        BadCase{"res_too_low", svg(kCrease), "2x21", 2, {"2x21", "at least 3"}},
        BadCase{"res_even", svg(kCrease), "30x21", 2, {"30x21", "odd", "31x21"}},
        BadCase{"res_too_high", svg(kCrease), "2003x21", 2, {"2003x21", "2001"}},
        BadCase{"res_garbage", svg(kCrease), "abc", 2, {"\"abc\"", "31x21"}}),
    [](const auto& info) { return info.param.name; });

TEST(BadInputFiles, AMissingFileIsAnInputErrorNamingIt) {
  const auto r = test::run_sdog("mesh /nonexistent/pattern.svg --res 21x21");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(test::count_lines(r.err), 1);
  EXPECT_NE(r.err.find("/nonexistent/pattern.svg"), std::string::npos) << r.err;
}

TEST(BadInputFiles, DirectoryInsteadOfFile) {
  const std::string dir = test::temp_dir("dir_as_file");
  const auto r = test::run_sdog("mesh " + dir + " --res 21x21");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(test::count_lines(r.err), 1);
  EXPECT_NE(r.err.find(dir), std::string::npos) << r.err;
}

TEST(BadInputFiles, AnUnwritableOutputDirectoryIsAnOutputError) {
  const std::string dir = test::temp_dir("unwritable");
  const std::string blocker = test::write_file(dir, "file", "x");
  const auto r = test::run_sdog("mesh " + test::dataset("one_curve.svg") + " --res 21x21 --out " +
                                blocker + "/sub");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(test::count_lines(r.err), 1);
  EXPECT_NE(r.err.find(blocker), std::string::npos) << r.err;
}

// The thesis grid's folder: one option name for both commands (and the other spelling accepted),
// a missing folder named in one line before any work starts.
TEST(BadInputFiles, MissingThesisPatternsFolder) {
  const std::string out = test::temp_dir("grid_missing");
  for (const std::string& command :
       {std::string("bench --thesis-grid"), "compare --thesis-grid --modes standard --out " + out})
    for (const char* option : {"--patterns-dir", "--patterns"}) {
      const auto r = test::run_sdog(command + " " + option + " /nonexistent/thesis");
      EXPECT_EQ(r.code, 1) << command << " " << option << ": " << r.err;
      EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
      EXPECT_NE(r.err.find("/nonexistent/thesis/1_curve.svg: thesis pattern not found"),
                std::string::npos)
          << r.err;
    }
}

TEST(BadInputFiles, MissingResolutionValueIsAUsageError) {
  const auto r = test::run_sdog("mesh " + test::dataset("one_curve.svg") + " --res");
  EXPECT_EQ(r.code, 2);
}

TEST(BadInputFiles, UnknownOptionIsAUsageError) {
  const auto r = test::run_sdog("mesh " + test::dataset("one_curve.svg") + " --bogus");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--bogus"), std::string::npos) << r.err;
}

TEST(BadInputFiles, AnUnknownCommandIsNamed) {
  const auto r = test::run_sdog("frobnicate " + test::dataset("one_curve.svg"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(
                "unknown command 'frobnicate'; the commands are mesh, render, run, bench, compare"),
            std::string::npos)
      << r.err;
  const auto none = test::run_sdog("");
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("no command given"), std::string::npos) << none.err;
}

// A value out of range given on the command line is a usage error (2); the same value from a
// configuration file is an input error (1).
TEST(BadInputFiles, AnOptionValueThatCannotWorkIsAUsageError) {
  const auto r =
      test::run_sdog("run " + test::dataset("one_curve.svg") + " --res 11x11 --rho -1 -q");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("command line: $.admm.rho must be positive"), std::string::npos) << r.err;
  const std::string dir = test::temp_dir("rho_in_file");
  const std::string config = test::write_file(dir, "c.json", R"({"admm": {"rho": -1}})");
  const auto f = test::run_sdog("run " + test::dataset("one_curve.svg") +
                                " --res 11x11 -q --config " + config);
  EXPECT_EQ(f.code, 1) << f.err;
  EXPECT_NE(f.err.find("c.json"), std::string::npos) << f.err;
  EXPECT_NE(f.err.find("rho"), std::string::npos) << f.err;
}

TEST(Version, NamesTheReleaseAndTheCommit) {
  const auto r = test::run_sdog("--version");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("sdog 0.", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("(commit "), std::string::npos) << r.out;
}

TEST(NoCreases, IsOnePatchNotAnError) {
  const std::string dir = test::temp_dir("no_creases");
  const std::string path = test::write_file(dir, "empty.svg", svg(""));
  const auto r = test::run_sdog("mesh " + path + " --res 11x7 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["fine"]["patches"], 1);
  EXPECT_EQ(j["fine"]["vertices"], 77);
  EXPECT_EQ(j["fine"]["quads"], 60);
  EXPECT_EQ(j["coarse"]["vertices"], 6 * 4);
  EXPECT_EQ(j["map"]["coarse_only"], 0);
}

}  // namespace
}  // namespace sdog
