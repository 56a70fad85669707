// The interactive session (session.h) and workspaces (workspace.h): stepping, handles dragged by
// program, angle constraints added and removed, crease assignments and angles set, undo and redo,
// mode switches, and a workspace saved and loaded back.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/errors.h"
#include "geometry/input/pattern_file.h"
#include "geometry/mesh/dog_model.h"
#include "solver/problem/scenario.h"
#include "solver/run/run_setup.h"
#include "solver/session/session.h"
#include "solver/session/workspace.h"
#include "solver/terms/fold_angles.h"
#include "tests/solver/session_fixture.h"
#include "tests/test_support.h"

namespace sdog {
namespace {

const DogModel& model() {
  return test::session_model();
}
using test::interactive;

TEST(Session, StepsTheBaseScenario) {
  Session s(model(), RunConfig{}, ModeKind::kStandard);
  const Dofs start = s.positions();
  for (int k = 0; k < 5; ++k) {
    const IterationReport r = s.step();
    ASSERT_FALSE(r.step.failed) << r.step.failure;
    EXPECT_EQ(r.iteration, k + 1);
    EXPECT_EQ(r.mode, "standard");
    EXPECT_LT(r.diagnostics.dog_max, 1e-4);
  }
  EXPECT_EQ(s.iteration(), 5);
  EXPECT_GT((s.positions() - start).norm(), 1e-3);
  s.reset();
  EXPECT_EQ(s.iteration(), 0);
  EXPECT_EQ(s.positions(), start);
}

TEST(Session, DraggedHandleLeadsTheSheetAndUndoRestoresIt) {
  Session s(model(), interactive(), ModeKind::kStandard);
  const int last = model().fine.vertex_count() - 1;
  EXPECT_EQ(s.add_handle(0), 0);
  EXPECT_EQ(s.add_handle(last), 1);
  const Eigen::Vector3d rest = vertex_of(s.positions(), last);
  const Eigen::Vector3d lifted = rest + Eigen::Vector3d(0, 0, 3);
  s.move_handle(1, lifted);
  // The handle moves 3 mesh units at once; the solver follows it in sub-steps until converged.
  bool converged = false;
  for (int k = 0; k < 150 && !converged; ++k) {
    const IterationReport r = s.step();
    ASSERT_FALSE(r.step.failed) << r.step.failure;
    converged = r.step.converged.value_or(false);
  }
  EXPECT_TRUE(converged);
  EXPECT_LT((vertex_of(s.positions(), last) - lifted).norm(), 0.5);
  EXPECT_LT(vertex_of(s.positions(), 0).norm(), 0.5);  // the held corner stays
  EXPECT_EQ(s.scenario().positions.size(), 2u);

  ASSERT_TRUE(s.undo());  // the move
  EXPECT_EQ(s.constraints().handles[1].target, rest);
  ASSERT_TRUE(s.undo());  // the second handle
  EXPECT_EQ(s.constraints().handles.size(), 1u);
  EXPECT_EQ(s.scenario().positions.size(), 1u);
  ASSERT_TRUE(s.redo());
  ASSERT_TRUE(s.redo());
  EXPECT_FALSE(s.can_redo());
  EXPECT_EQ(s.constraints().handles[1].target, lifted);
  s.remove_handle(0);
  EXPECT_EQ(s.constraints().handles.size(), 1u);
  EXPECT_EQ(s.constraints().handles[0].vertex, last);
  EXPECT_THROW(s.add_handle(model().fine.vertex_count()), InputError);
  EXPECT_THROW(s.move_handle(5, lifted), InputError);
}

TEST(Session, ADragIsOneEditAndSeveralHandlesAreAddedAtOnce) {
  Session s(model(), interactive(), ModeKind::kStandard);
  const int last = model().fine.vertex_count() - 1;
  EXPECT_EQ(s.add_handles({0, 1, last}), 0);
  ASSERT_EQ(s.constraints().handles.size(), 3u);
  EXPECT_EQ(s.scenario().positions.size(), 3u);
  EXPECT_EQ(s.constraints().handles[2].vertex, last);
  const Eigen::Vector3d rest = s.constraints().handles[2].target;
  // A drag: the first move is a new edit, the following ones continue it, while the solver steps.
  for (int k = 1; k <= 5; ++k) {
    s.move_handle(2, rest + Eigen::Vector3d(0, 0, 0.5 * k), /*merge=*/k > 1);
    ASSERT_FALSE(s.step().step.failed);
    EXPECT_EQ(s.scenario().positions.back().end, rest + Eigen::Vector3d(0, 0, 0.5 * k));
  }
  ASSERT_TRUE(s.undo());  // the whole drag
  EXPECT_EQ(s.constraints().handles[2].target, rest);
  EXPECT_EQ(s.constraints().handles.size(), 3u);
  ASSERT_TRUE(s.undo());  // the three handles
  EXPECT_TRUE(s.constraints().handles.empty());
  EXPECT_FALSE(s.can_undo());
  EXPECT_THROW(s.add_handles({}), InputError);
  EXPECT_THROW(s.add_handles({0, last + 1}), InputError);
  EXPECT_TRUE(s.constraints().handles.empty());  // nothing added when one vertex is wrong
}

TEST(Session, UndoAndRedoNameTheirEdits) {
  Session s(model(), interactive(), ModeKind::kStandard);
  EXPECT_EQ(s.undo_name(), "");
  s.add_handles({0, 1});
  EXPECT_EQ(s.undo_name(), "make 2 handles");
  s.move_handle(1, Eigen::Vector3d(0, 0, 1));
  s.move_handle(1, Eigen::Vector3d(0, 0, 2), /*merge=*/true);
  EXPECT_EQ(s.undo_name(), "move handle 1");
  s.set_creases({0, 1}, Fold::kValley, std::nullopt);
  EXPECT_EQ(s.undo_name(), "set 2 creases valley");
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(s.redo_name(), "set 2 creases valley");
  EXPECT_EQ(s.undo_name(), "move handle 1");
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(s.undo_name(), "make 2 handles");
  EXPECT_EQ(s.redo_name(), "move handle 1");
  s.remove_handle(0);
  EXPECT_EQ(s.undo_name(), "remove handle 0");
  EXPECT_EQ(s.redo_name(), "");
}

TEST(Session, AHandleTakesOverTheScenariosTargetOfItsVertex) {
  Session s(model(), RunConfig{}, ModeKind::kStandard);  // the corners scenario
  const size_t corners = s.scenario().positions.size();
  ASSERT_GE(corners, 2u);
  for (int k = 0; k < 3; ++k) ASSERT_FALSE(s.step().step.failed);
  const PositionConstraint corner = s.scenario().positions.front();
  const Eigen::Vector3d dragged = corner.end + Eigen::Vector3d(1, 2, 3);
  EXPECT_EQ(s.add_handle_at(corner.vertex, dragged), 0);
  // Still one target per corner: the handle's replaces the scenario's.
  ASSERT_EQ(s.scenario().positions.size(), corners);
  int on_vertex = 0;
  for (const auto& p : s.scenario().positions)
    if (p.vertex == corner.vertex) {
      ++on_vertex;
      EXPECT_EQ(p.start, dragged);
      EXPECT_EQ(p.end, dragged);
    }
  EXPECT_EQ(on_vertex, 1);
  EXPECT_EQ(s.undo_name(), "take the scenario's target of vertex " + std::to_string(corner.vertex));
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(s.scenario().positions.front().end, corner.end);
  EXPECT_THROW(s.add_handle_at(-1, dragged), InputError);
}

TEST(Session, AngleConstraintFoldsItsCreasePointAndCanBeRemoved) {
  const auto& points = model().fine.stitching.points;
  int site = -1;
  for (size_t p = 0; p < points.size() && site < 0; ++p)
    if (points[p].copies.size() == 2 && p > points.size() / 3) site = static_cast<int>(p);
  ASSERT_GE(site, 0);
  auto angle_term_after = [&](bool with_angle) {
    auto s = std::make_unique<Session>(model(), interactive(), ModeKind::kStandard);
    s->add_handle(0);
    if (with_angle) {
      EXPECT_EQ(s->add_angle(site, 60), 0);
    }
    // The crease point starts folding after 20 to 30 steps from the flat sheet.
    for (int k = 0; k < 40; ++k) EXPECT_FALSE(s->step().step.failed);
    return s;
  };
  const auto with_session = angle_term_after(true);
  Session& with = *with_session;
  EXPECT_EQ(with.scenario().angles.size(), 1u);
  EXPECT_LT(with.problem().angles.block_count(), 2);
  // The constrained crease point bends: its sheet leaves the plane.
  double lift = 0;
  for (int v = 0; v < model().fine.vertex_count(); ++v)
    lift = std::max(lift, std::abs(with.positions()[3 * v + 2]));
  EXPECT_GT(lift, 0.5);
  with.remove_angle(0);
  EXPECT_TRUE(with.scenario().angles.empty());
  ASSERT_TRUE(with.undo());
  EXPECT_EQ(with.scenario().angles.size(), 1u);
  EXPECT_THROW(with.add_angle(static_cast<int>(points.size()), 30), InputError);
  EXPECT_THROW(with.add_angle(site, 200), InputError);
}

TEST(Session, CreaseEditsFoldTheSessionsModelAndAreUndone) {
  // The configuration's crease settings apply to the session's copy of the model, not the given
  // one.
  RunConfig config;
  config.scenario = ScenarioKind::kFold;
  config.creases.push_back({"test", 1, std::nullopt, Fold::kMountain, 45.0});
  Session s(model(), config, ModeKind::kStandard);
  EXPECT_EQ(s.model().fine.stitching.curves[1].fold, Fold::kMountain);
  EXPECT_EQ(s.model().fine.stitching.curves[1].angle, std::optional<double>(45.0));
  EXPECT_EQ(model().fine.stitching.curves[1].angle, std::nullopt);
  const Fold drawn = model().fine.stitching.curves[0].fold;
  const Fold flipped = drawn == Fold::kMountain ? Fold::kValley : Fold::kMountain;
  // The fold scenario's targets on crease 0 follow its assignment and angle.
  auto target_of = [&](int curve) {
    return crease_fold_target(s.model().fine, curve, config.fold_angle);
  };
  s.set_creases({0}, flipped, std::nullopt);
  s.set_creases({0}, std::nullopt, 30.0);
  EXPECT_EQ(s.model().fine.stitching.curves[0].fold, flipped);
  EXPECT_EQ(s.model().clean.creases[0].angle, std::optional<double>(30.0));
  EXPECT_DOUBLE_EQ(target_of(0), flipped == Fold::kValley ? 30.0 : -30.0);
  EXPECT_DOUBLE_EQ(target_of(1), -45.0);
  // The edits are settings of the configuration: the later one with the whole state replaces the
  // earlier one of the crease.
  ASSERT_EQ(s.config().creases.size(), 2u);
  EXPECT_EQ(s.config().creases.back().curve, std::optional<int>(0));
  EXPECT_EQ(s.config().creases.back().angle, std::optional<double>(30.0));
  for (int k = 0; k < 3; ++k) ASSERT_FALSE(s.step().step.failed);
  s.fold();
  EXPECT_EQ(s.iteration(), 0);
  EXPECT_EQ(s.config().scenario, ScenarioKind::kFold);
  ASSERT_TRUE(s.undo());  // the angle
  EXPECT_EQ(s.model().fine.stitching.curves[0].fold, flipped);
  EXPECT_EQ(s.model().fine.stitching.curves[0].angle, model().fine.stitching.curves[0].angle);
  ASSERT_TRUE(s.undo());  // the assignment
  EXPECT_EQ(s.model().fine.stitching.curves[0].fold, drawn);
  EXPECT_EQ(s.config().creases.size(), 1u);
  ASSERT_TRUE(s.redo());
  EXPECT_EQ(s.model().fine.stitching.curves[0].fold, flipped);
  s.set_creases({0, 1}, Fold::kFlat, std::nullopt);
  EXPECT_DOUBLE_EQ(target_of(0), 0.0);
  EXPECT_DOUBLE_EQ(target_of(1), 0.0);
  EXPECT_FALSE(s.can_redo());
  EXPECT_THROW(s.set_creases({99}, Fold::kValley, std::nullopt), InputError);
  EXPECT_THROW(s.set_creases({0}, std::nullopt, 200.0), InputError);
  EXPECT_THROW(s.set_creases({}, Fold::kValley, std::nullopt), InputError);
}

// Slits and seams do not fold: an edit of their assignment is refused before it changes anything.
TEST(Session, SlitsAndSeamsRefuseAnAssignment) {
  const DogModel slits =
      build_dog_model(read_crease_pattern(test::dataset("slits_and_tab.svg")), {21, 21});
  Session s(slits, interactive(), ModeKind::kStandard);
  const auto& curves = s.model().fine.stitching.curves;
  ASSERT_EQ(curves[1].kind, CurveKind::kSlit);
  ASSERT_EQ(curves[3].kind, CurveKind::kSeam);
  for (const int k : {1, 3}) {
    try {
      s.set_creases({0, k}, Fold::kMountain, std::nullopt);
      FAIL() << "crease " << k << " took an assignment";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("crease " + std::to_string(k) + " is a"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_FALSE(s.can_undo()) << "no edit was made";
  EXPECT_EQ(s.model().fine.stitching.curves[0].fold, Fold::kValley);
  EXPECT_TRUE(s.config().creases.empty());
}

// The fold amount (the studio's slider) folds the sheet to a share of every crease's angle and back
// to flat; at 100% the session ends on the same side as `sdog run` with the same settings.
TEST(Session, TheFoldAmountFoldsAndUnfoldsTheSheetOnTheRunsSide) {
  const DogModel m =
      build_dog_model(read_crease_pattern(test::dataset("curved_pleats.svg")), {21, 21});
  RunConfig config;
  config.scenario = ScenarioKind::kFold;
  config.fold_angle = 60;
  config.iterations = 1;
  config.hold = 30;
  const FoldAngles angles(m.fine);
  auto converge = [&](Session& s) {
    for (int k = 0; k < 60; ++k) {
      const IterationReport r = s.step();
      EXPECT_FALSE(r.step.failed) << r.step.failure;
      if (r.step.converged.value_or(false) && r.step.target_fraction >= 1) return;
    }
    ADD_FAILURE() << "the session did not converge in 60 iterations";
  };
  // Each fold site's angle over its crease's full (100%) target.
  auto shares = [&](const Dofs& x) {
    std::vector<double> out;
    for (size_t k = 0; k < angles.sites().size(); ++k) {
      const double target = crease_fold_target(m.fine, angles.sites()[k].curve, config.fold_angle);
      if (target != 0) out.push_back(angles.at(k, x) / target);
    }
    return out;
  };
  RunSetup run(m, ModeKind::kStandard, config);
  ASSERT_EQ(run.run({}).termination, Termination::kCompleted);
  const std::vector<double> by_run = shares(run.positions());

  Session s(m, config, ModeKind::kStandard);
  s.set_fold_percent(100);
  converge(s);
  const std::vector<double> full = shares(s.positions());
  ASSERT_EQ(full.size(), by_run.size());
  ASSERT_FALSE(full.empty());
  for (size_t k = 0; k < full.size(); ++k) {
    EXPECT_NEAR(full[k], 1.0, 0.1) << "site " << k;
    EXPECT_GT(full[k] * by_run[k], 0)
        << "site " << k << ": the session and the run fold it different ways";
  }
  s.set_fold_percent(50);
  EXPECT_EQ(s.config().fold_percent, 50);
  converge(s);
  for (double share : shares(s.positions())) EXPECT_NEAR(share, 0.5, 0.1);
  s.set_fold_percent(0);
  converge(s);
  for (size_t k = 0; k < angles.sites().size(); ++k)
    EXPECT_LT(std::abs(angles.at(k, s.positions())), 3) << k;
  EXPECT_THROW(s.set_fold_percent(101), InputError);
  EXPECT_THROW(s.set_fold_percent(-1), InputError);
}

TEST(Session, ModeSwitchKeepsThePositions) {
  Session s(model(), RunConfig{}, ModeKind::kStandard);
  for (int k = 0; k < 10; ++k) ASSERT_FALSE(s.step().step.failed);
  const Dofs before = s.positions();
  s.set_mode(ModeKind::kTwoLevel);
  EXPECT_EQ(s.positions(), before);
  EXPECT_EQ(s.mode(), ModeKind::kTwoLevel);
  ASSERT_NE(s.coarse_positions(), nullptr);
  EXPECT_EQ(s.coarse_positions()->size(), 3 * model().coarse.vertex_count());
  const IterationReport r = s.step();
  ASSERT_FALSE(r.step.failed) << r.step.failure;
  EXPECT_EQ(r.mode, "twolevel");
  EXPECT_EQ(r.iteration, 11);
  EXPECT_LT(r.diagnostics.dog_max, 1e-4);
  EXPECT_THROW(s.set_mode(parse_enum<ModeKind>("warp")), UsageError);
}

}  // namespace
}  // namespace sdog
