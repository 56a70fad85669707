#include "solver/run/run_log.h"

#include <cstdio>
#include <functional>

namespace sdog {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string count(int v) {
  return std::to_string(v);
}

template <class Row>
struct Column {
  const char* name;
  std::function<std::string(const Row&)> field;
};

const std::vector<Column<IterationReport>>& run_columns() {
  using R = IterationReport;
  auto term = [](int k) { return [k](const R& r) { return number(r.diagnostics.terms[k]); }; };
  static const std::vector<Column<R>> columns = {
      {"iteration", [](const R& r) { return count(r.iteration); }},
      {"t", [](const R& r) { return number(r.t); }},
      {"objective", [](const R& r) { return number(r.diagnostics.objective); }},
      {"bending", term(kBending)},
      {"isometry", term(kIsometry)},
      {"positions", term(kPositions)},
      {"edge_points", term(kEdgePoints)},
      {"stitching", term(kStitching)},
      {"angles", term(kAngles)},
      {"fold_bias", term(kFoldBias)},
      {"objective_final_targets", [](const R& r) { return number(r.objective_final_targets); }},
      {"dog_max", [](const R& r) { return number(r.diagnostics.dog_max); }},
      {"dog_l2", [](const R& r) { return number(r.diagnostics.dog_l2); }},
      {"stitch_gap_max", [](const R& r) { return number(r.diagnostics.stitch_gap_max); }},
      {"edge_strain_max", [](const R& r) { return number(r.diagnostics.edge_strain_max); }},
      {"sheet_strain_max", [](const R& r) { return number(r.diagnostics.sheet_strain_max); }},
      {"sqp_steps", [](const R& r) { return count(r.step.work.steps); }},
      {"step_length", [](const R& r) { return number(r.step.step_length); }},
      {"fold_retries", [](const R& r) { return count(r.step.work.fold_retries); }},
      {"folded", [](const R& r) { return std::string(r.step.folded ? "1" : "0"); }},
      {"iteration_ms", [](const R& r) { return number(r.iteration_ms); }},
      {"factor_ms", [](const R& r) { return number(r.step.work.factor_ms); }},
      {"link", term(kLink)},
      {"factorizations", [](const R& r) { return count(r.step.work.factorizations); }},
      {"restoration_steps", [](const R& r) { return count(r.step.work.restoration_steps); }},
      {"mode", [](const R& r) { return r.mode; }},
      {"converged",
       [](const R& r) {
         return r.step.converged ? std::string(*r.step.converged ? "1" : "0") : std::string();
       }},
      {"target_fraction", [](const R& r) { return number(r.step.target_fraction); }},
      {"settling", [](const R& r) { return r.step.stage; }},
      {"elapsed_ms", [](const R& r) { return number(r.elapsed_ms); }},
      {"direction_agreement",
       [](const R& r) {
         const AngleAgreement& a = r.diagnostics.angles_met;
         return a.targeted_sites > 0 ? number(a.direction_agreement()) : std::string();
       }},
      {"angle_error",
       [](const R& r) {
         const AngleAgreement& a = r.diagnostics.angles_met;
         return a.targeted_sites > 0 ? number(a.median_error) : std::string();
       }},
      {"recovered_failures", [](const R& r) { return count(r.step.work.recovered_failures); }},
  };
  return columns;
}

// A patch row: the iteration and its mode with one patch report.
struct PatchRow {
  const IterationReport& iteration;
  const PatchReport& patch;
};

const std::vector<Column<PatchRow>>& patch_columns() {
  using P = PatchRow;
  static const std::vector<Column<P>> columns = {
      {"iteration", [](const P& r) { return count(r.iteration.iteration); }},
      {"mode", [](const P& r) { return r.iteration.mode; }},
      {"patch", [](const P& r) { return count(r.patch.patch); }},
      {"thread", [](const P& r) { return count(r.patch.thread); }},
      {"start_ms", [](const P& r) { return number(r.patch.start_ms); }},
      {"ms", [](const P& r) { return number(r.patch.ms); }},
      {"linear_ms", [](const P& r) { return number(r.patch.work.factor_ms); }},
      {"steps", [](const P& r) { return count(r.patch.work.steps); }},
      {"factorizations", [](const P& r) { return count(r.patch.work.factorizations); }},
      {"objective", [](const P& r) { return number(r.patch.objective); }},
      {"dog_max", [](const P& r) { return number(r.patch.dog_max); }},
      {"converged", [](const P& r) { return std::string(r.patch.converged ? "1" : "0"); }},
  };
  return columns;
}

template <class Row>
std::vector<std::string> names(const std::vector<Column<Row>>& columns) {
  std::vector<std::string> out;
  for (const auto& c : columns) out.push_back(c.name);
  return out;
}

template <class Row>
std::string line(const std::vector<Column<Row>>& columns, const Row& row) {
  std::string out;
  for (const auto& c : columns) out += (out.empty() ? "" : ",") + c.field(row);
  return out + "\n";
}

std::string header(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ",") + n;
  return out + "\n";
}

}  // namespace

std::vector<std::string> run_csv_columns() {
  return names(run_columns());
}
std::string run_csv_header() {
  return header(run_csv_columns());
}
std::string run_csv_row(const IterationReport& r) {
  return line(run_columns(), r);
}
std::vector<std::string> run_csv_time_columns() {
  return {"iteration_ms", "factor_ms"};
}

std::vector<std::string> patches_csv_columns() {
  return names(patch_columns());
}
std::string patches_csv_header() {
  return header(patches_csv_columns());
}

std::string patches_csv_rows(const IterationReport& r) {
  std::string rows;
  for (const PatchReport& p : r.step.patches) rows += line(patch_columns(), PatchRow{r, p});
  return rows;
}

}  // namespace sdog
