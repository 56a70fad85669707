// The ADMM modes (vsadmm, jadmm, proxjadmm): the augmented terms act in the patch objectives,
// three constraint rows per stitching pair, DOG constraints every iteration, per-patch reports,
// thread-count independence.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "base/errors.h"
#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/modes/admm_mode.h"
#include "solver/modes/mode_factory.h"
#include "solver/problem/diagnostics.h"
#include "solver/run/run.h"
#include "solver/terms/crease_geometry.h"
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

class AdmmModes : public ::testing::TestWithParam<const char*> {};

TEST_P(AdmmModes, KeepTheDogConstraintsAndReportEveryPatch) {
  const Result r = run_admm(GetParam(), test::short_run(10, 2), 2);
  ASSERT_FALSE(r.summary.failed()) << r.summary.failure;
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
  ASSERT_FALSE(strong.summary.failed()) << strong.summary.failure;
  ASSERT_FALSE(weak.summary.failed()) << weak.summary.failure;
  EXPECT_LT(strong.reports.back().diagnostics.stitch_gap_max,
            0.5 * weak.reports.back().diagnostics.stitch_gap_max);
}

TEST_P(AdmmModes, SameResultWhateverTheThreadCount) {
  RunConfig config = test::short_run(5, 0);
  config.admm.inner = 2;
  const Result one = run_admm(GetParam(), config, 1);
  const Result two = run_admm(GetParam(), config, 2);
  ASSERT_FALSE(one.summary.failed()) << one.summary.failure;
  EXPECT_TRUE(one.x == two.x);
  // Two rounds per iteration: each patch's report covers both.
  for (const auto& p : two.reports.back().step.patches) EXPECT_GE(p.work.steps, 2);
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
    auto mode = make_mode(parse_enum<ModeKind>(name), problem, scenario, config);
    Dofs y = x;
    const double gap0 = diagnose(problem, y).stitch_gap_max;
    const RunSummary s = run_scenario(*mode, problem, scenario, y, {});
    ASSERT_FALSE(s.failed()) << name << ": " << s.failure;
    EXPECT_LT(s.last.diagnostics.stitch_gap_max, 0.5 * gap0) << name;
    EXPECT_GT(dynamic_cast<const AdmmMode&>(*mode).multipliers().front().norm(), 0) << name;
  }
}

// jadmm and proxjadmm are left out: with the angle targets coupling the patches their stitching
// gap grows about 2.4 times per iteration once the fold nears its end (four_corner_arcs 15x15 at 60
// degrees: 0.11 at iteration 15, 5.2 at 20, 950 at 26), the divergence the thesis reports for
// prox-JADMM.
TEST(AdmmMode, VsadmmFollowsAngleConstraints) {
  test::expect_follows_angles("vsadmm", model());
}

}  // namespace
}  // namespace sdog
