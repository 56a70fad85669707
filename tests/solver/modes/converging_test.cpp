// Converging iterations of the standard mode (standard_mode.h): far targets are followed by
// continuation, an unreachable target leaves the sheet as close as it can get, and a converged,
// held state costs nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "geometry/pattern/crease_pattern.h"
#include "solver/experiments/pace.h"
#include "solver/session/session.h"
#include "tests/solver/session_fixture.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

const DogModel& model() {
  return test::session_model();
}

Eigen::Vector3d vertex_of(const Dofs& x, int v) {
  return x.segment<3>(3 * v);
}

struct Followed {
  bool failed = false;
  bool converged = false;
  int iterations = 0;
  int partial_iterations = 0;  ///< that got only part of the way to the targets (continuation)
  double distance = 0;         ///< of the dragged corner to its target at the end
  double held_distance = 0;    ///< of the held corner to its target at the end
  double dog_max = 0;
  double stitch_gap_max = 0;
  double worst_dog_max = 0;  ///< over every iteration
  int factorizations = 0;
};

// The first grid corner held, the last one's target moved by `move` at once; steps until an
// iteration reports convergence (at most max_iterations).
Followed follow(const Eigen::Vector3d& move, bool converge, int max_iterations,
                std::optional<double> substep_tolerance = std::nullopt) {
  RunConfig config = test::interactive();
  config.standard.converge = converge;
  if (substep_tolerance) config.standard.substep_constraint_tolerance = *substep_tolerance;
  Session s(model(), config, ModeKind::kStandard);
  const int last = model().fine.vertex_count() - 1;
  s.add_handle(0);
  s.add_handle(last);
  const Eigen::Vector3d target = vertex_of(s.positions(), last) + move;
  s.move_handle(1, target);
  const Eigen::Vector3d held = vertex_of(s.positions(), 0);
  Followed f;
  while (f.iterations < max_iterations && !f.converged) {
    const IterationReport r = s.step();
    ++f.iterations;
    if (r.step.failed) {
      f.failed = true;
      break;
    }
    f.converged = r.step.converged.value_or(false);
    if (r.step.target_fraction < 1) ++f.partial_iterations;
    f.dog_max = r.diagnostics.dog_max;
    f.stitch_gap_max = r.diagnostics.stitch_gap_max;
    f.worst_dog_max = std::max(f.worst_dog_max, r.diagnostics.dog_max);
    f.factorizations += r.step.work.factorizations;
  }
  f.distance = (vertex_of(s.positions(), last) - target).norm();
  f.held_distance = (vertex_of(s.positions(), 0) - held).norm();
  return f;
}

// The sheet of the session model is 20 mesh units wide: the dragged corner is set at once onto
// the far side of the sheet, folding it over along the other diagonal. Continuation gets there
// and converges; one SQP step per iteration does not get there in as many iterations.
TEST(Continuation, FollowsATargetSetFarAwayUntilConverged) {
  const Eigen::MatrixX3d& rest = model().fine.V;
  const Eigen::Vector3d move =
      0.8 * (rest.row(0) - rest.row(rest.rows() - 1)).transpose() + Eigen::Vector3d(0, 0, 4);
  const Followed f = follow(move, true, 400);
  ASSERT_FALSE(f.failed);
  EXPECT_TRUE(f.converged) << "after " << f.iterations << " iterations";
  EXPECT_GE(f.partial_iterations, 3) << "no continuation: the target was reached in few iterations";
  EXPECT_LT(f.distance, 0.5);
  EXPECT_LT(f.dog_max, 1e-4);
  EXPECT_LT(f.stitch_gap_max, 1e-4);
  // The thesis's iteration, one SQP step, is still far from the target after as many iterations.
  const Followed one_step = follow(move, false, f.iterations);
  ASSERT_FALSE(one_step.failed);
  EXPECT_GT(one_step.distance, 1) << "after " << one_step.iterations << " iterations";
}

// Between the sub-steps of one iteration the restoration stops at substep_constraint_tolerance;
// the iteration's state is restored to the constraint tolerance once, at its end. The same far
// target costs fewer factorisations than with every sub-step restored to the constraint
// tolerance, and every iteration still ends within it.
TEST(Continuation, LooseSubstepsSaveFactorizationsAndEveryIterationEndsFeasible) {
  const Eigen::MatrixX3d& rest = model().fine.V;
  const Eigen::Vector3d move =
      0.8 * (rest.row(0) - rest.row(rest.rows() - 1)).transpose() + Eigen::Vector3d(0, 0, 4);
  const double tolerance = RunConfig{}.standard.sqp.constraint_tolerance;
  EXPECT_GT(RunConfig{}.standard.substep_constraint_tolerance,
            100 * tolerance);  // the default is loose
  const Followed loose = follow(move, true, 400);
  const Followed tight = follow(move, true, 400, tolerance);
  for (const Followed* f : {&loose, &tight}) {
    ASSERT_FALSE(f->failed);
    EXPECT_TRUE(f->converged);
    EXPECT_LT(f->distance, 0.5);
    EXPECT_LE(f->worst_dog_max, 1.01 * tolerance);
  }
  EXPECT_LT(loose.factorizations, 0.9 * tight.factorizations)
      << "loose " << loose.factorizations << ", tight " << tight.factorizations;
}

// A target 50 units off the sheet, in its plane and away from the held corner. Were the sheet
// rigid, the two corners' distances to their targets would add up to 50 at best (the sheet flat
// along the line between the targets); the isometry is a soft term, so the pull stretches it a
// little and the sum ends below 50. The iteration converges there, without a failure.
TEST(Continuation, AnUnreachableTargetConvergesAsCloseAsTheSheetAllows) {
  const Eigen::MatrixX3d& rest = model().fine.V;
  const Eigen::Vector3d away = (rest.row(rest.rows() - 1) - rest.row(0)).transpose().normalized();
  const Followed f = follow(50 * away, true, 600);
  ASSERT_FALSE(f.failed);
  EXPECT_TRUE(f.converged) << "after " << f.iterations << " iterations";
  EXPECT_LT(f.distance + f.held_distance, 50);
  EXPECT_GT(f.held_distance, 1);  // the whole sheet is pulled along
  EXPECT_LT(f.dog_max, 1e-4);
}

// parallel_curves_4 at 43x31 (cells 2.3 times as tall as wide) with the targets set at once: in
// every held iteration one crease unfolds and the fold-bias retry refolds it, so the held
// iterations cycle around the same objective and a full step never becomes small. Five held
// iterations in a row that do not lower the objective make the state converged, and the run stops
// spending factorisations on it.
TEST(Continuation, HeldIterationsThatCycleCountAsConverged) {
  SDOG_REQUIRE_SHARED();
  const DogModel m = build_dog_model(
      read_crease_pattern(test::reference_patterns_dir() + "/parallel_curves_4.svg"),
      parse_resolution("43x31"));
  const PaceResult r = run_pace(m, RunConfig{}, 1, 40);
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  ASSERT_TRUE(r.time_to_shape_s.has_value()) << "no held iteration converged in " << r.iterations;
  EXPECT_LT(r.iterations, 30);
  EXPECT_LT(r.factorizations, 800);
  EXPECT_TRUE(r.folded);
  EXPECT_LE(r.dog_max, 1e-6);
}

// A paced run counts as converged only where its last state meets the final tolerance: a final
// tolerance no restoration reaches leaves a shaped run unconverged.
TEST(Continuation, APacedRunIsConvergedOnlyWithinTheFinalTolerance) {
  RunConfig config;
  const PaceResult reached = run_pace(model(), config, 1, 40);
  ASSERT_TRUE(reached.failure.empty()) << reached.failure;
  ASSERT_TRUE(reached.time_to_shape_s.has_value());
  EXPECT_TRUE(reached.converged);
  EXPECT_LE(reached.dog_max, 2 * config.standard.sqp.final_constraint_tolerance);

  config.standard.sqp.final_constraint_tolerance = 1e-15;
  const PaceResult missed = run_pace(model(), config, 1, 40);
  ASSERT_TRUE(missed.failure.empty()) << missed.failure;
  ASSERT_TRUE(missed.time_to_shape_s.has_value());
  EXPECT_GT(missed.dog_max, 2e-15);
  EXPECT_FALSE(missed.converged);
}

// Once converged, a held state costs no factorisation, and says it is converged.
TEST(Continuation, HeldConvergedIterationsCostNothing) {
  RunConfig config = test::interactive();
  Session s(model(), config, ModeKind::kStandard);
  const int last = model().fine.vertex_count() - 1;
  s.add_handle(0);
  s.add_handle(last);
  s.move_handle(1, vertex_of(s.positions(), last) + Eigen::Vector3d(0, 0, 2));
  bool converged = false;
  for (int k = 0; k < 200 && !converged; ++k) converged = s.step().step.converged.value_or(false);
  ASSERT_TRUE(converged);
  const Dofs x = s.positions();
  for (int k = 0; k < 3; ++k) {
    const IterationReport r = s.step();
    EXPECT_EQ(r.step.work.factorizations, 0);
    EXPECT_EQ(r.step.converged, std::optional<bool>(true));
    EXPECT_EQ(r.step.target_fraction, 1);
  }
  EXPECT_EQ(s.positions(), x);
}

}  // namespace
}  // namespace sdog
