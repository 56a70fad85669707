// The reference pages say what the programs do: their generated tables match the option
// definitions (`make reference-docs` renews them), and the output-files page names every column
// the programs write.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/reference.h"
#include "solver/config/reference.h"
#include "solver/experiments/tables.h"
#include "solver/run/run_log.h"
#include "tests/app/run_sdog.h"

namespace sdog {
namespace {

const char* const kMarker = "<!-- generated tables below: make reference-docs -->\n";

std::string page(const std::string& name) {
  return test::slurp(std::string(SDOG_DOCS_DIR) + "/reference/" + name);
}

// The part of a reference page after the marker line.
std::string generated_part(const std::string& name) {
  const std::string text = page(name);
  const size_t at = text.find(kMarker);
  if (at == std::string::npos) return "(no marker line in " + name + ")";
  return text.substr(at + std::string(kMarker).size());
}

TEST(ReferenceDocs, TheCommandLineTablesMatchTheOptionDefinitions) {
  EXPECT_EQ(generated_part("command-line.md"), cli::command_line_reference())
      << "docs/reference/command-line.md is out of date: run `make reference-docs`";
}

TEST(ReferenceDocs, TheConfigurationTablesMatchTheOptionTables) {
  EXPECT_EQ(generated_part("configuration.md"), configuration_reference())
      << "docs/reference/configuration.md is out of date: run `make reference-docs`";
}

TEST(ReferenceDocs, TheGeneratedTablesListEveryOptionAndKey) {
  const std::string cli = cli::command_line_reference();
  for (const char* option :
       {"`--res`", "`--mode`", "`--switch`", "`--thesis-grid`", "`--plot-size`", "`--screenshot`",
        "`--measure-fps`", "`--keep-failed`"})
    EXPECT_NE(cli.find(option), std::string::npos) << option;
  const std::string config = configuration_reference();
  for (const char* key : {"`kkt_tolerance`", "`rho_max`", "`polish_epsilon`", "`coarse_every`",
                          "`p`", "`backend`", "`fold_bias`", "`angle`"})
    EXPECT_NE(config.find(key), std::string::npos) << key;
  EXPECT_NE(config.find("| `rho_max` | number > 0 | `1e+12` |"), std::string::npos);
}

// datasets/README.md describes every dataset in its table and shows its preview (`make previews`).
TEST(ReferenceDocs, EveryDatasetIsDescribedAndPreviewed) {
  namespace fs = std::filesystem;
  const std::string readme = test::slurp(std::string(SDOG_DATASETS_DIR) + "/README.md");
  int datasets = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(SDOG_DATASETS_DIR)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".svg" && ext != ".fold") continue;
    ++datasets;
    const std::string file = e.path().filename().string(), name = e.path().stem().string();
    EXPECT_NE(readme.find("| `" + file + "` |"), std::string::npos)
        << file << " is not in the table";
    EXPECT_NE(readme.find("![" + name + "](../docs/datasets/" + name + ".png)"), std::string::npos)
        << file << " has no preview: run `make previews`";
    EXPECT_TRUE(fs::exists(fs::path(SDOG_DOCS_DIR) / "datasets" / (name + ".png")))
        << name << ".png";
  }
  EXPECT_GE(datasets, 17);
}

// The keys in the first column of the table under `heading` (up to the next heading).
std::set<std::string> table_keys(const std::string& text, const std::string& heading) {
  std::set<std::string> keys;
  const size_t start = text.find("\n" + heading + "\n");
  if (start == std::string::npos) return {"(no heading " + heading + ")"};
  std::istringstream in(text.substr(start + heading.size() + 2));
  for (std::string line; std::getline(in, line) && line.rfind("#", 0) != 0;)
    if (line.rfind("| `", 0) == 0) keys.insert(line.substr(3, line.find('`', 3) - 3));
  return keys;
}

std::set<std::string> json_keys(const nlohmann::json& j) {
  std::set<std::string> keys;
  for (const auto& item : j.items()) keys.insert(item.key());
  return keys;
}

// The tables of `sdog mesh --json` and run.json list exactly the keys the programs write.
TEST(ReferenceDocs, TheJsonTablesListExactlyTheKeysWritten) {
  const std::string text = page("output-files.md");
  const auto mesh =
      test::run_sdog("mesh " + test::dataset("one_curve.svg") + " --res 11x11 --json");
  ASSERT_EQ(mesh.code, 0) << mesh.err;
  EXPECT_EQ(table_keys(text, "## `sdog mesh --json`"), json_keys(nlohmann::json::parse(mesh.out)));
  const std::string dir = test::temp_dir("run_json_keys");
  const auto run =
      test::run_sdog("run " + test::dataset("one_curve.svg") +
                     " --res 11x11 --scenario fold --iters 2 --hold 0 -q --out " + dir + "/run");
  ASSERT_EQ(run.code, 0) << run.err;
  // A fold run has every key but `failure` (failed runs only).
  std::set<std::string> written =
      json_keys(nlohmann::json::parse(test::slurp(dir + "/run/run.json")));
  EXPECT_EQ(written.count("creases"), 1u);
  written.insert("failure");
  EXPECT_EQ(table_keys(text, "### `run.json`"), written);
}

// CHANGELOG.md: releases as "## X.Y.Z (YYYY-MM-DD)" (newest first, above them at most an
// "## Unreleased"), the newest being the version sdog reports; lines of at most 100 characters.
TEST(ReferenceDocs, TheChangelogIsInDatedReleasesOfTheReportedVersion) {
  const std::string text = test::slurp(std::string(SDOG_DOCS_DIR) + "/../CHANGELOG.md");
  std::istringstream in(text);
  std::vector<std::string> releases;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    size_t chars = 0;  // UTF-8 characters
    for (unsigned char c : line) chars += (c & 0xC0) != 0x80;
    EXPECT_LE(chars, 100u) << "CHANGELOG.md:" << number;
    if (line.rfind("## ", 0) != 0) continue;
    if (line == "## Unreleased") {
      EXPECT_TRUE(releases.empty()) << "CHANGELOG.md:" << number << ": Unreleased comes first";
      continue;
    }
    std::smatch m;
    ASSERT_TRUE(
        std::regex_match(line, m, std::regex(R"(## (\d+\.\d+\.\d+) \(\d{4}-\d{2}-\d{2}\))")))
        << "CHANGELOG.md:" << number << ": " << line;
    releases.push_back(m[1].str());
  }
  ASSERT_FALSE(releases.empty());
  const auto version = test::run_sdog("--version");
  EXPECT_EQ(version.out.rfind("sdog " + releases.front() + " ", 0), 0u) << version.out;
}

TEST(ReferenceDocs, TheOutputFilesPageNamesEveryColumn) {
  const std::string text = page("output-files.md");
  std::vector<std::vector<std::string>> tables = {run_csv_columns(), patches_csv_columns(),
                                                  bench_columns(), compare_columns(),
                                                  series_columns()};
  for (const auto& columns : tables)
    for (const std::string& c : columns)
      EXPECT_NE(text.find("| `" + c + "` |"), std::string::npos)
          << "column " << c << " is not described";
}

}  // namespace
}  // namespace sdog
