#include "solver/experiments/benchmark.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "base/errors.h"
#include "solver/modes/mode_factory.h"
#include "solver/run/run.h"
#include "solver/run/run_config.h"

namespace sdog {
double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

std::optional<double> paired_speedup(const std::vector<double>& reference_ms, const std::vector<double>& ms) {
  if (ms.empty() || ms.size() != reference_ms.size()) return std::nullopt;
  std::vector<double> ratios;
  for (size_t k = 0; k < ms.size(); ++k) ratios.push_back(reference_ms[k] / ms[k]);
  return median(ratios);
}

void relate_bench_to_standard(std::vector<BenchResult>& results) {
  const auto standard =
      std::find_if(results.begin(), results.end(), [](const BenchResult& r) { return r.mode == "standard"; });
  if (standard == results.end()) return;
  const BenchResult reference = *standard;
  for (auto& r : results) {
    r.speedup = reference.median_ms / r.median_ms;
    r.speedup_paired = paired_speedup(reference.run_medians, r.run_medians);
  }
}

bool in_timing_window(int iteration) { return iteration >= 10 && iteration <= 240; }

double median_iteration_ms(const std::vector<double>& iteration_ms) {
  std::vector<double> window;
  for (size_t k = 0; k < iteration_ms.size(); ++k)
    if (in_timing_window(static_cast<int>(k) + 1)) window.push_back(iteration_ms[k]);
  return median(window.empty() ? iteration_ms : window);
}

DogModel build_case_model(const BenchCase& c) {
  MeshOptions mesh_options;
  mesh_options.build_coarse = mode_needs_coarse(c.mode);
  return build_dog_model(read_crease_pattern(c.pattern), parse_resolution(c.res), mesh_options);
}

RunSummary run_case(const DogModel& model, const std::string& mode_name, const RunConfig& config,
                    const std::vector<RunObserver*>& observers) {
  DogProblem problem(model.fine, model.fine_topology, config.weights);
  const Scenario scenario = make_scenario(config, model.fine);
  check_scenario_targets(scenario, config, model.pattern.source + " at " + model.fine_res.str());
  auto mode = make_mode(mode_name, problem, scenario, config, &model);
  Dofs x = scenario.start(model.fine);
  return run_scenario(*mode, problem, scenario, x, observers);
}

namespace {

struct Recorder : RunObserver {
  int repeat = 0, total = 0;
  std::vector<double> iteration_ms;
  double factor_ms = 0, sqp_steps = 0, factorizations = 0, worst_dog = 0;
  int window = 0;
  const BenchProgress* progress = nullptr;
  const BenchCase* bench_case = nullptr;
  void on_iteration(const IterationReport& r, const Dofs&) override {
    worst_dog = std::max(worst_dog, r.diagnostics.dog_max);
    iteration_ms.push_back(r.iteration_ms);
    if (in_timing_window(r.iteration)) {
      ++window;
      factor_ms += r.step.factor_ms;
      sqp_steps += r.step.sqp_steps;
      factorizations += r.step.factorizations;
    }
    if (progress && *progress) (*progress)(*bench_case, repeat, r.iteration, total);
  }
};

// One case of a benchmark while its rounds run: the sums over its runs' timing windows.
struct BenchRuns {
  DogModel model;
  BenchResult result;
  double factor_ms = 0, sqp_steps = 0, factorizations = 0;
  int window = 0;
};

BenchRuns start_bench_case(const BenchCase& c) {
  BenchRuns runs{build_case_model(c), {}};
  BenchResult& result = runs.result;
  result.pattern = std::filesystem::path(c.pattern).stem().string();
  result.res = c.res;
  result.mode = c.mode;
  result.vertices = runs.model.fine.vertex_count();
  result.dof = 3 * result.vertices;
  return runs;
}

void finish_bench_case(BenchRuns& runs) {
  BenchResult& result = runs.result;
  result.median_ms = median(result.run_medians);
  result.ms_per_dof = result.median_ms / result.dof;
  if (runs.window > 0) {
    result.factor_ms = runs.factor_ms / runs.window;
    result.sqp_steps = runs.sqp_steps / runs.window;
    result.factorizations = runs.factorizations / runs.window;
  }
}

}  // namespace

std::vector<BenchResult> run_benchmark_rounds(const std::vector<BenchCase>& cases, const BenchOptions& options,
                                              const BenchProgress& progress) {
  RunConfig config;
  config.iterations = options.iterations;
  config.hold = options.iterations / 5;
  std::vector<BenchRuns> runs;
  for (const auto& c : cases) runs.push_back(start_bench_case(c));
  for (int k = 0; k < std::max(1, options.repeat); ++k) {
    for (size_t i = 0; i < cases.size(); ++i) {
      BenchRuns& b = runs[i];
      BenchResult& result = b.result;
      Recorder rec;
      rec.repeat = k;
      rec.total = config.iterations + config.hold;
      rec.progress = &progress;
      rec.bench_case = &cases[i];
      const RunSummary s = run_case(b.model, cases[i].mode, config, {&rec});
      if (s.failed) throw SolverError(result.pattern + " " + cases[i].res + " " + cases[i].mode + ": " + s.failure);
      result.run_medians.push_back(median_iteration_ms(rec.iteration_ms));
      b.factor_ms += rec.factor_ms;
      b.sqp_steps += rec.sqp_steps;
      b.factorizations += rec.factorizations;
      b.window += rec.window;
      result.final_objective = s.last.diagnostics.objective;
      result.dog_max = s.last.diagnostics.dog_max;
      result.dog_max_over_run = std::max(result.dog_max_over_run, rec.worst_dog);
    }
  }
  std::vector<BenchResult> results;
  for (auto& b : runs) {
    finish_bench_case(b);
    results.push_back(std::move(b.result));
  }
  return results;
}

std::string csv_number(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string optional_csv_number(const std::optional<double>& v, int digits) {
  return v ? csv_number(*v, digits) : std::string();
}

std::string bench_csv_header() {
  return "pattern,res,mode,vertices,dof,median_ms,ms_per_dof,sqp_steps,factor_ms,final_objective,dog_max,"
         "factorizations,dog_max_over_run,repeats,speedup,speedup_paired\n";
}

std::string bench_csv_row(const BenchResult& r) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%s,%s,%s,%d,%d,%.4g,%.4g,%.4g,%.4g,%.6g,%.3g,%.4g,%.3g,%zu,", r.pattern.c_str(),
                r.res.c_str(), r.mode.c_str(), r.vertices, r.dof, r.median_ms, r.ms_per_dof, r.sqp_steps, r.factor_ms,
                r.final_objective, r.dog_max, r.factorizations, r.dog_max_over_run, r.run_medians.size());
  return buf + optional_csv_number(r.speedup, 4) + "," + optional_csv_number(r.speedup_paired, 4) + "\n";
}

std::vector<BenchCase> thesis_grid(const std::string& dir, const std::string& mode) {
  const std::pair<const char*, std::vector<const char*>> grid[] = {
      {"1_curve", {"31x21", "43x31", "55x41", "81x59"}},
      {"4_corners", {"21x21", "41x41", "61x61", "81x81"}},
      {"valley", {"21x21", "41x41", "61x61", "81x81"}},
      {"parallel_curves_4", {"27x45", "39x65", "45x75", "51x85"}}};
  std::vector<BenchCase> cases;
  for (const auto& [name, resolutions] : grid) {
    const std::string path = dir + "/" + name + ".svg";
    if (!std::filesystem::exists(path))
      throw InputError(path + ": thesis pattern not found (pass the folder of the thesis patterns with --patterns-dir)");
    for (const char* res : resolutions) cases.push_back({path, res, mode});
  }
  return cases;
}

}  // namespace sdog
