// `sdog mesh` as a user runs it: counts, JSON, files, help.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "tests/app/run_sdog.h"

namespace sdog {
namespace {

TEST(MeshCommand, JsonMatchesTheLibrary) {
  const auto r =
      test::run_sdog("mesh " + test::dataset("crossing_creases.svg") + " --res 21x21 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("crossing_creases.svg")), {21, 21});
  EXPECT_EQ(j["fine"]["vertices"], m.fine.vertex_count());
  EXPECT_EQ(j["fine"]["quads"], m.fine.quad_count());
  EXPECT_EQ(j["fine"]["patches"], 4);
  EXPECT_EQ(j["fine"]["crease_points"], m.fine.stitching.points.size());
  EXPECT_EQ(j["fine"]["stitch_pairs"], m.fine.stitching.pairs.size());
  EXPECT_EQ(j["coarse"]["vertices"], m.coarse.vertex_count());
  EXPECT_EQ(j["coarse"]["quads"], m.coarse.quad_count());
  EXPECT_EQ(j["map"]["link"], m.map.link_count);
  EXPECT_EQ(j["map"]["I"], m.map.i_count);
  EXPECT_EQ(j["map"]["X"], m.map.x_count);
  EXPECT_EQ(j["map"]["coarse_only"], m.map.coarse_only_count);
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
  const auto& classes = j["fine"]["vertex_classes"];
  EXPECT_EQ(classes["star"].get<int>() + classes["bnd3"].get<int>() + classes["bnd2"].get<int>() +
                classes["bnd4"].get<int>(),
            m.fine.vertex_count());
}

// one_curve's sheet is 600 x 400: at 41x7 its cells are 15 by 66.7, 4.4 times as tall as wide;
// 41x27 gives nearly square cells (15 by 15.4). `sdog mesh` lists the warning in its summary, the
// other commands print it to stderr and go on.
TEST(MeshCommand, WarnsAboutLongGridCells) {
  const std::string pattern = test::dataset("one_curve.svg");
  const std::string warning = "grid cells are 4.4 times as tall as wide";
  const auto json = test::run_sdog("mesh " + pattern + " --res 41x7 --json");
  ASSERT_EQ(json.code, 0) << json.err;
  const auto warnings = nlohmann::json::parse(json.out)["warnings"];
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].get<std::string>().find(warning), std::string::npos) << warnings;
  EXPECT_NE(warnings[0].get<std::string>().find("41x27"), std::string::npos) << warnings;
  EXPECT_EQ(json.err, "");
  const auto text = test::run_sdog("mesh " + pattern + " --res 41x7");
  EXPECT_NE(text.out.find("warning:    " + warning), std::string::npos) << text.out;
  const auto run = test::run_sdog("run " + pattern +
                                  " --res 41x7 --iters 1 --hold 0 --frames-every 0 -q --out " +
                                  test::temp_dir("long_cells"));
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.err.rfind("warning: " + warning, 0), 0u) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  const auto pace = test::run_sdog("bench --pace --pattern " + pattern + " --res 41x7 --ks 1");
  ASSERT_EQ(pace.code, 0) << pace.err;
  EXPECT_NE(pace.err.find("warning: " + warning), std::string::npos) << pace.err;
  const auto square = test::run_sdog("mesh " + pattern + " --res 41x27 --json");
  ASSERT_EQ(square.code, 0) << square.err;
  EXPECT_TRUE(nlohmann::json::parse(square.out)["warnings"].empty());
}

TEST(MeshCommand, CleaningAdaptsToADenseDrawingUnlessTheTolerancesAreGiven) {
  // Creases crossing within 5 units at angles down to 4 degrees on a 100-unit sheet.
  const std::string pattern =
      test::write_file(test::temp_dir("crowded"), "crowded.svg",
                       "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">"
                       "<line x1=\"50\" y1=\"0\" x2=\"50\" y2=\"100\" stroke=\"#f00\"/>"
                       "<line x1=\"0\" y1=\"80\" x2=\"100\" y2=\"20\" stroke=\"#00f\"/>"
                       "<line x1=\"0\" y1=\"48\" x2=\"100\" y2=\"51\" stroke=\"#f00\"/>"
                       "<line x1=\"0\" y1=\"45\" x2=\"100\" y2=\"54.5\" stroke=\"#00f\"/></svg>");
  const auto adapted = test::run_sdog("mesh " + pattern + " --res 41x41");
  ASSERT_EQ(adapted.code, 0) << adapted.err;
  EXPECT_NE(adapted.out.find("cleaned with --merge-tol 0.001 --snap-tol 0.002"), std::string::npos)
      << adapted.out;
  const auto chosen = test::run_sdog("mesh " + pattern + " --res 41x41 --merge-tol 0.01");
  EXPECT_EQ(chosen.code, 1);
  EXPECT_NE(chosen.err.find("no junction could be placed"), std::string::npos) << chosen.err;

  // Too low a resolution: the message names one that meshes, found by trying.
  const auto low = test::run_sdog("mesh " + pattern + " --res 5x5");
  EXPECT_EQ(low.code, 2);
  const std::string says = "; it meshes at ";
  const size_t at = low.err.find(says);
  ASSERT_NE(at, std::string::npos) << low.err;
  const std::string enough =
      low.err.substr(at + says.size(), low.err.find(',', at) - at - says.size());
  EXPECT_EQ(test::run_sdog("mesh " + pattern + " --res " + enough).code, 0) << enough;
  EXPECT_EQ(test::run_sdog("mesh " + pattern + " --res 9x9").code, 2)
      << "9x9 is lower than " << enough;
}

TEST(MeshCommand, TextSummaryNamesEveryCount) {
  const auto r = test::run_sdog("mesh " + test::dataset("one_curve.svg") + " --res 31x21");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* word : {"sheet", "creases", "fine", "coarse", "crease points", "stitching pairs",
                           "vertex classes", "link", "coarse-only", "time"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word << " missing in\n" << r.out;
}

TEST(MeshCommand, OutWritesTheVtkFilesAndThePatternAsFold) {
  const std::string dir = test::temp_dir("mesh_out") + "/nested/out";
  const auto r =
      test::run_sdog("mesh " + test::dataset("four_corner_arcs.svg") + " --res 21x21 --out " + dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"fine.vtu", "coarse.vtu", "creases.vtp", "pattern.vtp", "pattern.fold"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
    EXPECT_NE(r.out.find(f), std::string::npos) << "the summary should name " << f;
  }
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) (void)e, ++entries;
  EXPECT_EQ(entries, 5) << "temporary files left behind";
  // The FOLD file meshes into the same patches.
  const auto back = test::run_sdog("mesh " + dir + "/pattern.fold --res 21x21 --json");
  ASSERT_EQ(back.code, 0) << back.err;
  const auto first =
      test::run_sdog("mesh " + test::dataset("four_corner_arcs.svg") + " --res 21x21 --json");
  EXPECT_EQ(nlohmann::json::parse(back.out)["fine"], nlohmann::json::parse(first.out)["fine"]);
}

// one_curve's crease meets the sheet boundary at both ends; the alternative coarse DOG keeps
// neither end (the thesis's observation), so some of its fine crease points cannot be interpolated.
TEST(MeshCommand, CoarseAltBuildsTheFineDogWithoutEverySecondRowAndColumn) {
  const std::string dir = test::temp_dir("mesh_alt");
  const std::string pattern = test::dataset("one_curve.svg");
  const auto r =
      test::run_sdog("mesh " + pattern + " --res 41x27 --coarse alt --json --out " + dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["coarse"]["kind"], "alt");
  EXPECT_EQ(j["coarse"]["resolution"], "21x14");
  EXPECT_EQ(j["map"]["coarse_only"], 0);
  EXPECT_EQ(j["map"]["link"], j["coarse"]["vertices"]) << "every coarse vertex is a link";
  const DogModel standard = build_dog_model(read_crease_pattern(pattern), {41, 27});
  EXPECT_EQ(j["fine"], nlohmann::json::parse(
                           test::run_sdog("mesh " + pattern + " --res 41x27 --json").out)["fine"])
      << "the fine DOG does not depend on the coarse one";
  const auto& points = j["map"]["crease_points"];
  size_t fine_points = 0;
  for (const auto& curve : standard.fine.stitching.curves) fine_points += curve.points.size();
  EXPECT_EQ(points["kept"].get<size_t>() + points["interpolated"].get<size_t>() +
                points["uninterpolable"].get<size_t>(),
            fine_points);
  EXPECT_GT(points["kept"].get<int>(), 0);
  EXPECT_GT(points["uninterpolable"].get<int>(), 0);
  EXPECT_EQ(j["coarse"]["crease_points"], points["kept"]);
  // creases.vtp marks each crease point: kept, interpolated or not interpolable.
  std::ifstream vtp(dir + "/creases.vtp");
  const std::string text((std::istreambuf_iterator<char>(vtp)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("Name=\"coarse_point\""), std::string::npos);

  const auto summary = test::run_sdog("mesh " + pattern + " --res 41x27 --coarse alt");
  ASSERT_EQ(summary.code, 0) << summary.err;
  for (const char* words : {"coarse alt", "coarse-only 0",
                            "fine vertices the coarse mesh does "
                            "not reach",
                            "not interpolable"})
    EXPECT_NE(summary.out.find(words), std::string::npos) << words << " missing in\n"
                                                          << summary.out;
  const auto wrong = test::run_sdog("mesh " + pattern + " --res 41x27 --coarse thesis");
  EXPECT_EQ(wrong.code, 2);
  EXPECT_NE(wrong.err.find("--coarse"), std::string::npos) << wrong.err;
  const auto both = test::run_sdog("mesh " + pattern + " --res 41x27 --coarse alt --fine-only");
  EXPECT_EQ(both.code, 2);
  EXPECT_NE(both.err.find("--fine-only"), std::string::npos) << both.err;
}

TEST(MeshCommand, FineOnlyAcceptsEvenResolutions) {
  const auto r =
      test::run_sdog("mesh " + test::dataset("one_curve.svg") + " --res 30x20 --fine-only --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.contains("coarse"));
  EXPECT_EQ(j["fine"]["resolution"], "30x20");
}

TEST(MeshCommand, HelpExplainsEveryOption) {
  const auto top = test::run_sdog("--help");
  EXPECT_EQ(top.code, 0);
  EXPECT_NE(top.out.find("mesh"), std::string::npos);
  const auto r = test::run_sdog("mesh --help");
  EXPECT_EQ(r.code, 0);
  for (const char* opt : {"PATTERN", "--res", "--out", "--json", "--fine-only", "--flatness",
                          "--merge-tol", "--snap-tol", "--coarse"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

}  // namespace
}  // namespace sdog
