#include "solver/run/run_log.h"

#include <cstdio>

namespace sdog {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

}  // namespace

std::string run_csv_header() {
  return "iteration,t,objective,bending,isometry,positions,edge_points,stitching,angles,fold_bias,"
         "objective_final_targets,dog_max,dog_l2,stitch_gap_max,edge_strain_max,sqp_steps,step_length,"
         "fold_retries,folded,iteration_ms,factor_ms,link,factorizations,restoration_steps,mode\n";
}

std::vector<std::string> run_csv_time_columns() { return {"iteration_ms", "factor_ms"}; }

std::string run_csv_row(const IterationReport& r) {
  const Diagnostics& d = r.diagnostics;
  const StepReport& s = r.step;
  std::string row = std::to_string(r.iteration) + "," + number(r.t) + "," + number(d.objective);
  for (int k : {kBending, kIsometry, kPositions, kEdgePoints, kStitching, kAngles, kFoldBias})
    row += "," + number(d.terms[k]);
  for (double v : {r.objective_final_targets, d.dog_max, d.dog_l2, d.stitch_gap_max, d.edge_strain_max})
    row += "," + number(v);
  row += "," + std::to_string(s.sqp_steps) + "," + number(s.step_length) + "," + std::to_string(s.fold_retries) + "," +
         (s.folded ? "1" : "0") + "," + number(r.iteration_ms) + "," + number(s.factor_ms) + "," +
         number(d.terms[kLink]) + "," + std::to_string(s.factorizations) + "," +
         std::to_string(s.restoration_steps) + "," + r.mode + "\n";
  return row;
}

std::string patches_csv_header() {
  return "iteration,mode,patch,thread,start_ms,ms,linear_ms,steps,factorizations,objective,dog_max,converged\n";
}

std::string patches_csv_rows(const IterationReport& r) {
  std::string rows;
  for (const PatchReport& p : r.step.patches)
    rows += std::to_string(r.iteration) + "," + r.mode + "," + std::to_string(p.patch) + "," +
            std::to_string(p.thread) + "," + number(p.start_ms) + "," + number(p.ms) + "," + number(p.linear_ms) +
            "," + std::to_string(p.inner) + "," + std::to_string(p.factorizations) + "," + number(p.objective) +
            "," + number(p.dog_max) + "," + (p.converged ? "1" : "0") + "\n";
  return rows;
}

}  // namespace sdog
