// The ADMM modes (vsadmm, jadmm, proxjadmm) and the flatten scenario: the augmented terms act in
// the patch objectives, three constraint rows per stitching pair, DOG constraints every iteration,
// per-patch reports, thread-count independence, and the "admm" configuration.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <nlohmann/json.hpp>

#include "geometry/dog_model.h"
#include "base/errors.h"
#include "solver/modes/admm_mode.h"
#include "solver/terms/crease_geometry.h"
#include "solver/problem/diagnostics.h"
#include "solver/modes/mode_factory.h"
#include "solver/run/run.h"
#include "tests/solver/run_recorder.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

using Result = test::RunResult;
const char* const kAdmmModes[] = {"vsadmm", "jadmm", "proxjadmm"};

const DogModel& model() {
  static const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("four_corner_arcs.svg")), {15, 15});
  return m;
}

Result run_admm(const std::string& mode, const RunConfig& config, int threads) {
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
  return test::run_mode(mode, model(), config);
}

// The flatten scenario of the default configuration (its start state costs a fold run: built once).
const Scenario& flatten() {
  static const Scenario s = [] {
    RunConfig config;
    config.scenario = "flatten";
    config.iterations = 0;
    config.hold = 30;
    return make_scenario(config, model().fine);
  }();
  return s;
}

class AdmmModes : public ::testing::TestWithParam<const char*> {};

TEST_P(AdmmModes, KeepTheDogConstraintsAndReportEveryPatch) {
  const Result r = run_admm(GetParam(), test::short_run(10, 2), 2);
  ASSERT_FALSE(r.summary.failed) << r.summary.failure;
  ASSERT_EQ(r.reports.size(), 12u);
  test::expect_dog_and_patch_reports(r, model().fine.patch_count());
  // The last iteration's polish does not always reach the standard solver's 5e-7 on a patch with
  // augmented terms (measured up to 7e-6 here).
  EXPECT_LT(r.reports.back().diagnostics.dog_max, 1e-5);
}

TEST_P(AdmmModes, AugmentedTermsPullThePatchesTogether) {
  // The corner drag moves one patch; only the augmented terms make the others follow.
  RunConfig config = test::short_run(6, 0);
  config.admm.rho = 100;
  const Result strong = run_admm(GetParam(), config, 2);
  config.admm.rho = 1e-3;
  const Result weak = run_admm(GetParam(), config, 2);
  ASSERT_FALSE(strong.summary.failed) << strong.summary.failure;
  ASSERT_FALSE(weak.summary.failed) << weak.summary.failure;
  EXPECT_LT(strong.reports.back().diagnostics.stitch_gap_max,
            0.5 * weak.reports.back().diagnostics.stitch_gap_max);
}

TEST_P(AdmmModes, SameResultWhateverTheThreadCount) {
  RunConfig config = test::short_run(5, 0);
  config.admm.inner = 2;
  const Result one = run_admm(GetParam(), config, 1);
  const Result two = run_admm(GetParam(), config, 2);
  ASSERT_FALSE(one.summary.failed) << one.summary.failure;
  EXPECT_TRUE(one.x == two.x);
  // Two rounds per iteration: each patch's report covers both.
  for (const auto& p : two.reports.back().step.patches) EXPECT_GE(p.inner, 2);
}

INSTANTIATE_TEST_SUITE_P(Modes, AdmmModes, ::testing::ValuesIn(kAdmmModes));

TEST(AdmmMode, ThreeRowsPerStitchingPair) {
  // Shift the patch of one pair's copy a by (d, -d, 0): the copies' coordinate sums still agree (a
  // single row with t on the x, y and z columns, the reference's A, sees nothing), the three rows
  // do, and the modes pull the copies together again.
  const DogMesh& mesh = model().fine;
  const StitchConstraints rows(mesh);
  ASSERT_GT(rows.pair_count(), 0);
  const int patch = rows.side(0, 0).patch;
  const double d = 0.3;
  Dofs x = to_dofs(mesh.V);
  for (int v = mesh.patch_begin[patch]; v < mesh.patch_begin[patch + 1]; ++v) {
    x[3 * v] += d;
    x[3 * v + 1] -= d;
  }
  const Eigen::Vector3d r = rows.residual(0, x);
  EXPECT_NEAR(r.sum(), 0, 1e-12);
  EXPECT_NEAR(r.norm(), std::sqrt(2.0) * d, 1e-12);

  // jadmm is left out: on free rigid patches Jacobian ADMM diverges (each copy jumps to where the
  // other was; per row g' = -g + 2 lambda/rho, lambda'/rho = -lambda/rho + g, spectral radius
  // 1 + sqrt 2). The proximal term of proxjadmm, large enough (Deng et al.: P >= rho A_i^T A_i for
  // two blocks and gamma = 1), damps it.
  for (const char* name : {"vsadmm", "proxjadmm"}) {
    RunConfig config;
    config.admm.p = 2;
    DogProblem problem(mesh, model().fine_topology, config.weights);
    Scenario scenario;  // nothing asked: only the stitching rows act
    scenario.name = "none";
    scenario.iterations = 0;
    scenario.hold = 8;
    auto mode = make_mode(name, problem, scenario, config);
    Dofs y = x;
    const double gap0 = diagnose(problem, y).stitch_gap_max;
    const RunSummary s = run_scenario(*mode, problem, scenario, y, {});
    ASSERT_FALSE(s.failed) << name << ": " << s.failure;
    EXPECT_LT(s.last.diagnostics.stitch_gap_max, 0.5 * gap0) << name;
    EXPECT_GT(dynamic_cast<const AdmmMode&>(*mode).multipliers().front().norm(), 0) << name;
  }
}

TEST(AdmmMode, FollowAngleConstraints) {
  for (const char* name : kAdmmModes) test::expect_follows_angles(name, model());
}

TEST(FlattenScenario, StartsFoldedAndTheStandardModeFlattensIt) {
  const Scenario& s = flatten();
  ASSERT_EQ(s.positions.size(), 1u);
  EXPECT_TRUE(s.angles.empty());
  EXPECT_FALSE(s.keeps_folds);
  RunConfig config;
  DogProblem problem(model().fine, model().fine_topology, config.weights);
  const Dofs x0 = s.start(model().fine);
  const Diagnostics start = diagnose(problem, x0);
  EXPECT_TRUE(check_folded(model().fine, problem.sites, x0).folded);
  EXPECT_GT(start.terms[kBending], 0.1);
  const Result r = test::run_mode("standard", model(), config, s);
  ASSERT_FALSE(r.summary.failed) << r.summary.failure;
  for (const auto& rep : r.reports)
    EXPECT_LT(rep.diagnostics.dog_max, 1e-4) << "iteration " << rep.iteration;
  EXPECT_LT(r.reports.back().diagnostics.terms[kBending], 0.01 * start.terms[kBending]);
}

TEST(FlattenScenario, AnAdmmModeClosesTheStitchingGap) {
  RunConfig config;
  const Dofs x0 = flatten().start(model().fine);
  DogProblem problem(model().fine, model().fine_topology, config.weights);
  const double gap0 = diagnose(problem, x0).stitch_gap_max;
  const Result r = test::run_mode("vsadmm", model(), config, flatten());
  ASSERT_FALSE(r.summary.failed) << r.summary.failure;
  for (const auto& rep : r.reports)
    EXPECT_LT(rep.diagnostics.dog_max, 1e-4) << "iteration " << rep.iteration;
  // The first round opens the gap (lambda = 0: every patch starts flattening on its own), then the
  // multipliers close it.
  EXPECT_LT(r.reports.back().diagnostics.stitch_gap_max, 0.5 * gap0);
  EXPECT_LT(r.reports.back().diagnostics.stitch_gap_max,
            0.25 * r.reports.front().diagnostics.stitch_gap_max);
}

TEST(AdmmConfig, BadValuesNameTheJsonPath) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"admm": {"rho": -1}})", "c.json: $.admm.rho"},
      {R"({"admm": {"gamma": 0}})", "c.json: $.admm.gamma"},
      {R"({"admm": {"p": -0.5}})", "c.json: $.admm.p"},
      {R"({"admm": {"inner": 0}})", "c.json: $.admm.inner"},
      {R"({"admm": {"sigma": 1}})", "c.json: $.admm.sigma: unknown key"}};
  for (const auto& [text, message] : cases) {
    RunConfig config;
    try {
      apply_run_config(nlohmann::json::parse(text), "c.json", config);
      ADD_FAILURE() << text << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  RunConfig config;
  config.admm.rho = 0;
  try {
    validate_run_config(config, "c.json");
    ADD_FAILURE() << "rho 0 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c.json: $.admm.rho must be positive"), std::string::npos)
        << e.what();
  }
}

TEST(AdmmConfig, WrittenBackForRunJson) {
  RunConfig config;
  apply_run_config(nlohmann::json::parse(R"({"admm": {"rho": 10, "gamma": 0.5, "inner": 3}})"),
                   "c.json", config);
  const nlohmann::json j = to_json(config)["admm"];
  EXPECT_EQ(j["rho"], 10);
  EXPECT_EQ(j["gamma"], 0.5);
  EXPECT_EQ(j["inner"], 3);
  EXPECT_TRUE(j["p"].is_string());  // the default, 0.001 (patches - 1)
  RunConfig again;
  apply_run_config(nlohmann::json::parse(R"({"admm": {"p": 0.25}})"), "c.json", again);
  EXPECT_EQ(to_json(again)["admm"]["p"], 0.25);
  EXPECT_DOUBLE_EQ(again.admm.proximal_weight(4), 0.25);
  EXPECT_DOUBLE_EQ(config.admm.proximal_weight(4), 0.003);
}

}  // namespace
}  // namespace sdog
