// Grabbing and dragging handle targets (ui/control/handle_drag.h) and crease edits
// (crease_edit.h) without a window.
#include "ui/control/handle_drag.h"

#include <gtest/gtest.h>

#include "base/errors.h"
#include "ui/control/crease_edit.h"

namespace sdog::control {
namespace {

TEST(HandleDrag, GrabsTheUsersHandleOrTakesOverAScenarioTarget) {
  vis::ConstraintView drawn;
  drawn.handles = {{4, Eigen::Vector3d(0, 0, 0)}, {9, Eigen::Vector3d(1, 0, 0)}};
  Eigen::MatrixX3d display(2, 3);
  display << 100, 100, 0.3,  //
      200, 100, 0.6;
  UserConstraints user;
  user.handles = {{2, Eigen::Vector3d::Zero()}, {9, Eigen::Vector3d(1, 0, 0)}};

  const auto own = grab_target(drawn, display, user, 210, 100);
  ASSERT_TRUE(own);
  EXPECT_EQ(own->handle, 1) << "vertex 9 is the user's second handle";
  EXPECT_FALSE(own->new_handle);
  EXPECT_DOUBLE_EQ(own->depth, 0.6);

  const auto scenario = grab_target(drawn, display, user, 95, 105);
  ASSERT_TRUE(scenario);
  EXPECT_TRUE(scenario->new_handle) << "vertex 4 is the scenario's";
  EXPECT_EQ(scenario->vertex, 4);
  EXPECT_EQ(scenario->handle, 2) << "the new handle comes after the user's two";

  EXPECT_FALSE(grab_target(drawn, display, user, 150, 100)) << "50 pixels from both";
  EXPECT_FALSE(grab_target({}, Eigen::MatrixX3d(0, 3), user, 100, 100)) << "nothing drawn";
}

TEST(HandleDrag, TheFirstMoveStartsTheEditUnlessTheGrabDid) {
  HandleDrag drag;
  EXPECT_FALSE(drag.active());
  drag.begin({1, false, 9, Eigen::Vector3d::Zero(), 0.5});
  EXPECT_TRUE(drag.active());
  EXPECT_EQ(drag.handle(), 1);
  EXPECT_TRUE(drag.move()) << "the drag's first move";
  EXPECT_FALSE(drag.move()) << "later moves merge into it";
  EXPECT_EQ(drag.describe(Eigen::Vector3d(1, 2.5, -3)), "handle 1 at (1.00, 2.50, -3.00)");
  drag.end();
  EXPECT_FALSE(drag.active());
  drag.begin({2, true, 4, Eigen::Vector3d::Zero(), 0.5});
  EXPECT_FALSE(drag.move()) << "the new handle started the edit";
}

TEST(CreaseEdit, SaysWhatTheEditDoesOrWhyItCannot) {
  EXPECT_EQ(crease_edit_message({0, 3}, Fold::kValley, std::nullopt, ScenarioKind::kCorners),
            "2 crease(s) set to valley - Creases > Fold folds with the assignments");
  EXPECT_EQ(crease_edit_message({1}, std::nullopt, 45.5, ScenarioKind::kFold),
            "1 crease(s) set to 45.5 degrees - the fold goes on from the current shape (Creases > "
            "Fold starts "
            "again from flat)");
  EXPECT_THROW(crease_edit_message({}, Fold::kMountain, std::nullopt, ScenarioKind::kFold),
               UsageError);
  EXPECT_THROW(crease_edit_message({1}, std::nullopt, 181, ScenarioKind::kFold), UsageError);
  EXPECT_THROW(crease_edit_message({1}, std::nullopt, -1, ScenarioKind::kFold), UsageError);
}

}  // namespace
}  // namespace sdog::control
