// Robots as users bring them: MoveIt SRDFs as shipped (chains, links, subgroups, free group names,
// prefixed names), joints held still, continuous joints with and without <limit>, package:// paths.
#include <gtest/gtest.h>

#include <cmath>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/forward_kinematics.hpp"
#include "pmdplan/model/resource_path.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

// A prefixed arm (left_) with a two-joint hand; the head is continuous with and without a range.
const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="prefixed">
  <link name="left_base"/><link name="left_link1"/><link name="left_link2"/><link name="left_palm"/>
  <link name="left_finger"/><link name="left_finger_tip"/><link name="head"/><link name="camera"/>
  <joint name="left_joint1" type="revolute"><parent link="left_base"/><child link="left_link1"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="left_joint2" type="revolute"><parent link="left_link1"/><child link="left_link2"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="left_flange" type="fixed"><parent link="left_link2"/><child link="left_palm"/><origin xyz="0 0 0.2"/></joint>
  <joint name="left_finger_joint" type="revolute"><parent link="left_palm"/><child link="left_finger"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 1 0"/><limit lower="0" upper="1.5" effort="1" velocity="1"/></joint>
  <joint name="left_finger_tip_joint" type="revolute"><parent link="left_finger"/><child link="left_finger_tip"/>
    <origin xyz="0 0 0.04"/><axis xyz="0 1 0"/><limit lower="0" upper="1.5" effort="1" velocity="1"/>
    <mimic joint="left_finger_joint"/></joint>
  <joint name="head_pan" type="continuous"><parent link="left_base"/><child link="head"/>
    <origin xyz="0 0 1"/><axis xyz="0 0 1"/><limit lower="-0.5" upper="0.7" effort="1" velocity="1"/></joint>
  <joint name="camera_spin" type="continuous"><parent link="head"/><child link="camera"/>
    <origin xyz="0.1 0 0"/><axis xyz="1 0 0"/><limit effort="1" velocity="1"/></joint>
</robot>
)";

// As MoveIt Setup Assistant writes it for the unprefixed robot.
const char* kMoveItSrdf = R"(<?xml version="1.0"?>
<robot name="prefixed">
  <virtual_joint name="virtual_joint" type="fixed" parent_frame="world" child_link="base"/>
  <group name="panda_arm"><chain base_link="base" tip_link="link2"/></group>
  <group name="gripper"><link name="finger"/><link name="finger_tip"/></group>
  <group name="everything"><group name="panda_arm"/><group name="gripper"/></group>
  <group_state name="ready" group="panda_arm"><joint name="joint1" value="0"/></group_state>
  <end_effector name="hand" parent_link="palm" group="gripper" parent_group="panda_arm"/>
  <disable_collisions link1="link1" link2="link2" reason="Adjacent"/>
</robot>
)";

TEST(OwnRobotModel, AShippedMoveItSrdfWithUnprefixedNamesIsRead) {
  test::TempDir dir;
  const auto model = RobotModel::load(dir.write("r.urdf", kUrdf), dir.write("r.srdf", kMoveItSrdf));
  ASSERT_TRUE(model.hasGroup("arm"));
  ASSERT_TRUE(model.hasGroup("hand"));
  const auto names = model.activeJointNames();
  ASSERT_EQ(model.group("arm").size(), 2u);
  EXPECT_EQ(names[static_cast<std::size_t>(model.group("arm")[0])], "left_joint1");
  EXPECT_EQ(names[static_cast<std::size_t>(model.group("arm")[1])], "left_joint2");
  ASSERT_EQ(model.group("hand").size(), 1u);  // the tip mimics the finger
  EXPECT_EQ(names[static_cast<std::size_t>(model.group("hand")[0])], "left_finger_joint");
  EXPECT_EQ(model.group("everything").size(), 3u);
  EXPECT_EQ(model.links()[static_cast<std::size_t>(model.palmLink())].name, "left_palm");
  EXPECT_TRUE(model.isCollisionPairDisabled(model.linkIndex("left_link1"), model.linkIndex("left_link2")));
}

TEST(OwnRobotModel, AnAmbiguousNameListsTheCandidates) {
  test::TempDir dir;
  const std::string srdf = R"(<robot name="x"><group name="arm"><joint name="joint"/></group></robot>)";
  try {
    RobotModel::load(dir.write("r.urdf", kUrdf), dir.write("r.srdf", srdf));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("left_finger_tip_joint"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("left_finger_joint"), std::string::npos) << e.message();
  }
}

TEST(OwnRobotModel, ContinuousJointsHonourTheirLimitElseOneTurn) {
  test::TempDir dir;
  const auto model = RobotModel::load(dir.write("r.urdf", kUrdf));
  const auto& joints = model.activeJoints();
  const auto pan = static_cast<std::size_t>(model.activeIndex("head_pan"));
  const auto spin = static_cast<std::size_t>(model.activeIndex("camera_spin"));
  EXPECT_DOUBLE_EQ(joints[pan].lower, -0.5);
  EXPECT_DOUBLE_EQ(joints[pan].upper, 0.7);
  EXPECT_DOUBLE_EQ(joints[spin].lower, -M_PI);
  EXPECT_DOUBLE_EQ(joints[spin].upper, M_PI);
}

TEST(OwnRobotModel, HeldJointsLeaveTheConfigurationAndStayWhereHeld) {
  test::TempDir dir;
  const auto full = RobotModel::load(dir.write("r.urdf", kUrdf), dir.write("r.srdf", kMoveItSrdf));
  const auto held = full.withHeldJoints({{"left_joint2", 0.4}, {"left_finger_joint", 0.3}}, "fixed");
  EXPECT_EQ(held.dof(), full.dof() - 2);
  EXPECT_EQ(held.activeIndex("left_joint2"), -1);
  EXPECT_EQ(held.group("arm").size(), 1u);
  EXPECT_TRUE(held.group("hand").empty());
  ASSERT_TRUE(held.heldJointValue("left_joint2"));
  EXPECT_DOUBLE_EQ(*held.heldJointValue("left_joint2"), 0.4);
  // The same link poses as the full robot with those joints (and the mimic tip) at the held values.
  Configuration q(held.dof());
  for (int i = 0; i < held.dof(); ++i) q[i] = 0.1 * (i + 1);
  Configuration qFull(full.dof());
  for (const auto& name : full.activeJointNames()) {
    const int i = full.activeIndex(name);
    const int h = held.activeIndex(name);
    qFull[i] = h >= 0 ? q[h] : *held.heldJointValue(name);
  }
  const auto posesHeld = ForwardKinematics(held, Eigen::Isometry3d::Identity()).linkPoses(q);
  const auto posesFull = ForwardKinematics(full, Eigen::Isometry3d::Identity()).linkPoses(qFull);
  for (std::size_t l = 0; l < posesFull.size(); ++l)
    EXPECT_LT((posesHeld[l].matrix() - posesFull[l].matrix()).norm(), 1e-12) << full.links()[l].name;
  EXPECT_THROW(full.withHeldJoints({{"left_flange", 0.0}}, "fixed"), InputError);
}

TEST(OwnRobotModel, PackagePathsResolveThroughTheSearchPath) {
  test::TempDir dir;
  const auto urdf = dir.write("ws/src/my_robot/urdf/r.urdf", kUrdf);
  dir.write("ws/src/my_robot/meshes/m.stl", "solid m\nendsolid m\n");
  const auto from = dir.path() / "task.yaml";
  setPackageSearchPath(PackageSearchPath::parse("/nonexistent::" + (dir.path() / "ws/src").string()));
  EXPECT_EQ(resolveResourcePath("package://my_robot/urdf/r.urdf", from, "robot"), urdf);
  EXPECT_EQ(resolveResourcePath("file://" + urdf.string(), from, "robot"), urdf);
  EXPECT_EQ(resolveResourcePath("ws/src/my_robot/meshes/m.stl", from, "mesh"),
            dir.path() / "ws/src/my_robot/meshes/m.stl");
  try {
    resolveResourcePath("package://other/x.stl", from, "link[a].visual[0]");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), from.string());
    EXPECT_EQ(e.field(), "link[a].visual[0]");
    EXPECT_NE(e.message().find("/nonexistent:" + (dir.path() / "ws/src").string()), std::string::npos) << e.message();
  }
  setPackageSearchPath({});
}

}  // namespace
}  // namespace pmdplan
