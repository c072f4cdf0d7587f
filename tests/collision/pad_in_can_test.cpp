// Issue 37, Done when 1 (the checkers and the reference): the ring finger's distal pad box 2.2 mm
// inside can_on_table's goal can (support/pad_in_can.hpp). FCL 0.7's box-cylinder test calls it
// free; the exact checker's own route (primitive_contact.hpp) and the fast checker call it
// colliding, and the contact reference agrees, naming the same pair. The command-line side
// (check, plan, validate) is tests/cli/pad_in_can_cli_test.cpp.
#include "support/pad_in_can.hpp"

#include <fcl/fcl.h>
#include <gtest/gtest.h>

#include <cstdio>

#include "collision/reference_scene.hpp"
#include "pmdplan/collision/fast/fast_collision_checker.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

TEST(PadInCan, EveryCheckerAndTheReferenceCallItColliding) {
  test::TempDir dir;
  const Task task = loadTask(dir.write("pad_in_can.yaml", test::padInCanTaskText(dataDirectory() / "scenes")));
  const auto& joints = task.robot->activeJoints();
  ASSERT_EQ(joints.size(), test::kPadInCanJoints.size());
  for (std::size_t i = 0; i < joints.size(); ++i) ASSERT_EQ(joints[i].name, test::kPadInCanJoints[i]);
  for (std::size_t i = 0; i < joints.size(); ++i) ASSERT_EQ(task.goal[static_cast<int>(i)], test::kPadInCan[i]);

  ExactCollisionChecker exact(task), confirming(task);
  FastCollisionChecker fast(task, confirming);
  EXPECT_EQ(exact.check(task.goal).pairs, (std::vector<CollisionPair>{{"ring_distal_link", "goal_can"}}));
  EXPECT_FALSE(exact.isValid(task.goal));
  EXPECT_FALSE(fast.isValid(task.goal));
  const auto clearance = exact.clearance(task.goal, std::string("goal_can"));
  ASSERT_TRUE(clearance);
  EXPECT_LE(clearance->metres, -0.001) << "a lower bound on the depth, in metres";

  testing::ReferenceScene scene(task, exact);
  const auto contact = scene.penetration(task.goal, 1e-5);
  ASSERT_TRUE(contact);
  EXPECT_EQ(contact->pair, "ring_distal_link (box 2) - goal_can (cylinder 0)");
  EXPECT_NEAR(contact->metres, -0.00218, 0.00002);
  EXPECT_LE(contact->metres, clearance->metres + 1e-9) << "the checker's depth is a lower bound on the reference's";

  // What FCL 0.7 itself says of the pad box and the can (its independent GJK): printed, not held
  // against it, so that a fixed FCL does not fail this test.
  LinkPoses poses;
  exact.kinematics().linkPoses(task.goal, poses);
  const auto& ring = *std::find_if(task.robot->links().begin(), task.robot->links().end(),
                                   [](const auto& link) { return link.name == "ring_distal_link"; });
  const auto ringIndex = static_cast<std::size_t>(&ring - task.robot->links().data());
  const auto& pad = ring.collisionShapes[2];
  const auto& size = std::get<BoxShape>(pad.shape).size;
  const auto& can =
      *std::find_if(task.obstacles.begin(), task.obstacles.end(), [](const auto& o) { return o.name == "goal_can"; });
  const auto& cylinder = std::get<CylinderShape>(can.shape);
  fcl::Boxd box(size.x(), size.y(), size.z());
  fcl::Cylinderd fclCylinder(cylinder.radius, cylinder.length);
  fcl::CollisionRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;
  fcl::CollisionResultd result;
  fcl::collide(&box, poses[ringIndex] * pad.pose, &fclCylinder, can.pose, request, result);
  std::printf("[ pad in can ] reference %.3f mm, exact checker %.3f mm (colliding); FCL's box-cylinder: %s\n",
              contact->metres * 1e3, clearance->metres * 1e3, result.isCollision() ? "colliding" : "free");
}

}  // namespace
}  // namespace pmdplan
