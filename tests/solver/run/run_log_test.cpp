// The run log (run/run_log.h): one row per iteration with a field per column, in the columns'
// order, and one patches.csv row per patch.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "solver/run/run_log.h"

namespace sdog {
namespace {

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line.substr(0, line.find('\n')));
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

std::string field(const std::string& row, const std::vector<std::string>& columns,
                  const std::string& name) {
  const auto f = fields(row);
  for (size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i < f.size() ? f[i] : "(missing)";
  return "(no column " + name + ")";
}

IterationReport report() {
  IterationReport r;
  r.iteration = 7;
  r.mode = "twolevel";
  r.t = 0.25;
  r.diagnostics.objective = 2.5;
  r.diagnostics.terms[kBending] = 0.125;
  r.diagnostics.terms[kLink] = 3;
  r.diagnostics.dog_max = 4e-6;
  r.objective_final_targets = 9;
  r.step.work.steps = 2;
  r.step.work.factorizations = 3;
  r.step.work.restoration_steps = 4;
  r.step.work.fold_retries = 1;
  r.step.work.factor_ms = 1.5;
  r.step.folded = false;
  r.iteration_ms = 12.25;
  PatchReport p;
  p.patch = 1;
  p.thread = 1;
  p.ms = 3;
  p.work.steps = 5;
  p.work.factor_ms = 0.5;
  p.converged = true;
  r.step.patches = {p, p};
  r.step.patches[0].patch = 0;
  return r;
}

TEST(RunLog, ARowHasAFieldForEveryColumn) {
  const auto columns = run_csv_columns();
  EXPECT_EQ(fields(run_csv_header()), columns);
  const std::string row = run_csv_row(report());
  EXPECT_EQ(fields(row).size(), columns.size());
  EXPECT_EQ(field(row, columns, "iteration"), "7");
  EXPECT_EQ(field(row, columns, "t"), "0.25");
  EXPECT_EQ(field(row, columns, "objective"), "2.5");
  EXPECT_EQ(field(row, columns, "bending"), "0.125");
  EXPECT_EQ(field(row, columns, "link"), "3");
  EXPECT_EQ(field(row, columns, "dog_max"), "4e-06");
  EXPECT_EQ(field(row, columns, "objective_final_targets"), "9");
  EXPECT_EQ(field(row, columns, "sqp_steps"), "2");
  EXPECT_EQ(field(row, columns, "factorizations"), "3");
  EXPECT_EQ(field(row, columns, "restoration_steps"), "4");
  EXPECT_EQ(field(row, columns, "fold_retries"), "1");
  EXPECT_EQ(field(row, columns, "folded"), "0");
  EXPECT_EQ(field(row, columns, "iteration_ms"), "12.25");
  EXPECT_EQ(field(row, columns, "factor_ms"), "1.5");
  EXPECT_EQ(field(row, columns, "mode"), "twolevel");
  for (const std::string& time : run_csv_time_columns())
    EXPECT_NE(std::find(columns.begin(), columns.end(), time), columns.end()) << time;
}

TEST(RunLog, PatchRowsComeOnePerPatch) {
  const auto columns = patches_csv_columns();
  EXPECT_EQ(fields(patches_csv_header()), columns);
  const std::string rows = patches_csv_rows(report());
  std::stringstream in(rows);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(field(lines[1], columns, "patch"), "1");
  EXPECT_EQ(field(lines[0], columns, "patch"), "0");
  EXPECT_EQ(field(lines[1], columns, "steps"), "5");
  EXPECT_EQ(field(lines[1], columns, "linear_ms"), "0.5");
  EXPECT_EQ(field(lines[1], columns, "converged"), "1");
  EXPECT_EQ(field(lines[1], columns, "mode"), "twolevel");
  PatchesCsv csv;
  EXPECT_TRUE(csv.empty());
  csv.on_iteration(report(), Dofs());
  EXPECT_FALSE(csv.empty());
}

}  // namespace
}  // namespace sdog
