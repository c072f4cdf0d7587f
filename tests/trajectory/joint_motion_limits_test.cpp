// Joint limits for timing: velocities from the URDF, accelerations from the joint-limits file or
// the stated default, and a mimic joint's limits folded into its source's.
#include "pmdplan/trajectory/joint_motion_limits.hpp"

#include <gtest/gtest.h>

#include "pmdplan/core/input_error.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

const char* kUrdf = R"(<robot name="two">
  <link name="base"/><link name="a"/><link name="b"/>
  <joint name="lead" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="3"/></joint>
  <joint name="follower" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="1" velocity="4"/><mimic joint="lead" multiplier="2" offset="0"/></joint>
</robot>
)";

TEST(JointMotionLimits, AMimicJointBoundsItsSourceAndTheDefaultsApply) {
  test::TempDir dir;
  const RobotModel robot = RobotModel::load(dir.write("two.urdf", kUrdf));
  const auto limits = jointMotionLimits(robot);
  ASSERT_EQ(limits.size(), 1u);
  EXPECT_EQ(limits[0].name, "lead");
  EXPECT_DOUBLE_EQ(limits[0].velocity, 2.0);      // the follower moves twice as fast: 4 / 2
  EXPECT_DOUBLE_EQ(limits[0].acceleration, 4.0);  // default 2 s⁻¹ · 4 rad/s, halved: 4
}

TEST(JointMotionLimits, TheFileBesideTheUrdfGivesAccelerationsAndLowersVelocities) {
  test::TempDir dir;
  dir.write("two.joint_limits.yaml",
            "joint_limits:\n  lead: {max_velocity: 1.5, max_acceleration: 0.5}\n  follower: {max_acceleration: 8}\n");
  const RobotModel robot = RobotModel::load(dir.write("two.urdf", kUrdf));
  const auto limits = jointMotionLimits(robot);
  EXPECT_DOUBLE_EQ(limits[0].velocity, 1.5);
  EXPECT_DOUBLE_EQ(limits[0].acceleration, 0.5);
}

TEST(JointMotionLimits, MoveItsJointLimitsFileIsReadAsItShips) {
  test::TempDir dir;
  const RobotModel robot = RobotModel::load(dir.write("two.urdf", kUrdf));
  // The shape moveit_setup_assistant writes: scaling factors, every has_*/max_* pair, limits off
  // written as 0.
  const auto file = dir.write("joint_limits.yaml",
                              "default_velocity_scaling_factor: 0.1\ndefault_acceleration_scaling_factor: 0.1\n"
                              "joint_limits:\n  lead:\n    has_velocity_limits: true\n    max_velocity: 1.5\n"
                              "    has_acceleration_limits: true\n    max_acceleration: 0.5\n"
                              "    has_jerk_limits: false\n    max_jerk: 0\n    has_effort_limits: false\n"
                              "    max_effort: 0\n  follower:\n    has_velocity_limits: true\n    max_velocity: 4\n"
                              "    has_acceleration_limits: false\n    max_acceleration: 0\n");
  const auto limits = jointMotionLimits(robot, file);
  EXPECT_DOUBLE_EQ(limits[0].velocity, 1.5);
  EXPECT_DOUBLE_EQ(limits[0].acceleration, 0.5);  // the follower's "no limit" leaves the lead's own
  const auto missing = dir.write("m.yaml", "joint_limits:\n  lead: {has_acceleration_limits: true}\n");
  try {
    jointMotionLimits(robot, missing);
    ADD_FAILURE() << "accepted a limit flagged on without its value";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("max_acceleration is missing"), std::string::npos) << error.message();
  }
}

TEST(JointMotionLimits, BadFilesNameTheKey) {
  test::TempDir dir;
  const RobotModel robot = RobotModel::load(dir.write("two.urdf", kUrdf));
  const auto expectKey = [&](const std::string& text, const std::string& key) {
    const auto file = dir.write("bad.yaml", text);
    try {
      jointMotionLimits(robot, file);
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), file.string());
      EXPECT_NE(error.field().find(key), std::string::npos) << error.field() << ": " << error.message();
    }
  };
  expectKey("joint_limits:\n  nope: {max_acceleration: 1}\n", "joint_limits.nope");
  expectKey("joint_limits:\n  lead: {max_acceleration: 0}\n", "joint_limits.lead.max_acceleration");
  expectKey("joint_limits:\n  lead: {max_speed: 1}\n", "lead.max_speed");
  expectKey("joint_limits:\n  lead: {has_velocity_limits: yes, max_velocity: 1}\n", "lead.has_velocity_limits");
  expectKey("default_velocity_scaling_factor: 2x\njoint_limits: {}\n", "default_velocity_scaling_factor");
  EXPECT_THROW(jointMotionLimits(robot, dir.path() / "missing.yaml"), InputError);
}

TEST(JointMotionLimits, TheBuiltInRobotHasEveryJointsLimits) {
  const RobotModel robot = RobotModel::loadBuiltIn("sah_tx90");
  const auto limits = jointMotionLimits(robot);
  ASSERT_EQ(static_cast<int>(limits.size()), robot.dof());
  EXPECT_NEAR(limits[0].velocity, 6.981317007977, 1e-12);  // 400 °/s
  EXPECT_NEAR(limits[0].acceleration, 13.963, 1e-12);      // from sah_tx90.joint_limits.yaml
}

}  // namespace
}  // namespace pmdplan
