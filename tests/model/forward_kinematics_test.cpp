#include "pmdplan/model/forward_kinematics.hpp"

#include <gtest/gtest.h>

#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

// A planar two-link arm with a mimic joint: its FK has a closed form.
const char* kPlanarArm = R"(<?xml version="1.0"?>
<robot name="planar">
  <link name="base"/><link name="upper"/><link name="lower"/><link name="tip"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="lower"/>
    <origin xyz="1 0 0"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="wrist" type="revolute"><parent link="lower"/><child link="tip"/>
    <origin xyz="0.5 0 0"/><axis xyz="0 0 -1"/><limit lower="-3" upper="3" effort="1" velocity="1"/>
    <mimic joint="elbow" multiplier="0.5" offset="0.2"/></joint>
  <link name="slider_link"/>
  <joint name="slider" type="prismatic"><parent link="tip"/><child link="slider_link"/>
    <origin xyz="0.25 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="0.1" effort="1" velocity="1"/></joint>
</robot>
)";

TEST(ForwardKinematics, MatchesTheClosedFormOfAPlanarArmWithMimicAndPrismaticJoints) {
  test::TempDir dir;
  const auto model = RobotModel::load(dir.write("planar.urdf", kPlanarArm));
  ASSERT_EQ(model.dof(), 3);
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  base.translation() = Eigen::Vector3d(1, 2, 3);
  ForwardKinematics fk(model, base);
  for (const auto& [a, b, s] : {std::tuple{0.3, -0.7, 0.05}, std::tuple{-1.2, 2.1, 0.0}, std::tuple{2.5, 0.4, 0.1}}) {
    Configuration q(3);
    q << a, b, s;
    const auto values = fk.jointValues(q);
    EXPECT_DOUBLE_EQ(values[static_cast<std::size_t>(model.jointIndex("wrist"))], 0.5 * b + 0.2);
    const auto poses = fk.linkPoses(q);
    const double wrist = -(0.5 * b + 0.2);  // its axis is -z
    const double heading = a + b + wrist;
    const Eigen::Vector3d expected =
        Eigen::Vector3d(1, 2, 3.5) +
        Eigen::Vector3d(std::cos(a) + 0.5 * std::cos(a + b) + (0.25 + s) * std::cos(heading),
                        std::sin(a) + 0.5 * std::sin(a + b) + (0.25 + s) * std::sin(heading), 0);
    EXPECT_NEAR((poses[static_cast<std::size_t>(model.linkIndex("slider_link"))].translation() - expected).norm(), 0.0,
                1e-12);
  }
}

TEST(ForwardKinematics, RejectsAConfigurationOfTheWrongSize) {
  test::TempDir dir;
  const auto model = RobotModel::load(dir.write("planar.urdf", kPlanarArm));
  ForwardKinematics fk(model);
  EXPECT_THROW(fk.linkPoses(Configuration::Zero(2)), std::invalid_argument);
}

}  // namespace
}  // namespace pmdplan
