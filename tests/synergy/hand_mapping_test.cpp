#include "pmdplan/synergy/hand_mapping.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "pmdplan/glove/cyberglove_sensors.hpp"
#include "support/input_error_matchers.hpp"

namespace pmdplan {
namespace {

JointLimits mappedHand() {
  return {{"roll", 0.0, 1.5}, {"tilt", -0.25, 0.25}, {"bend", 0.0, 1.0}, {"spare", -0.2, 0.2}};
}

HandMapping mapping() {
  HandMapping m;
  m.sourceFile = "map.yaml";
  const int rotate = cyberGloveSensorIndex("ThumbRotate");
  m.rules = {{"roll", {{rotate, 1.0}}, 0.0, 3},
             {"tilt", {{rotate, -1.0 / 3.0}}, 0.25, 4},
             {"bend", {{cyberGloveSensorIndex("IndexMPJ"), 0.5}, {cyberGloveSensorIndex("IndexPIJ"), 0.5}}, 0.0, 5},
             {"spare", {}, 0.0, 6}};
  return m;
}

Eigen::MatrixXd angles(std::initializer_list<std::array<double, 3>> rows) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), kCyberGloveSensorCount);
  Eigen::Index f = 0;
  for (const auto& row : rows) {
    a(f, cyberGloveSensorIndex("ThumbRotate")) = row[0];
    a(f, cyberGloveSensorIndex("IndexMPJ")) = row[1];
    a(f, cyberGloveSensorIndex("IndexPIJ")) = row[2];
    ++f;
  }
  return a;
}

TEST(HandMapping, LinearFunctionsOfSensorsAndConstants) {
  const MappedPostures mapped = mapToJoints(angles({{0.75, 0.2, 0.4}}), mapping(), mappedHand());
  EXPECT_DOUBLE_EQ(mapped.postures(0, 0), 0.75);
  EXPECT_DOUBLE_EQ(mapped.postures(0, 1), 0.25 - 0.25);
  EXPECT_DOUBLE_EQ(mapped.postures(0, 2), 0.3);
  EXPECT_DOUBLE_EQ(mapped.postures(0, 3), 0.0);
  EXPECT_EQ(mapped.clampedValues, 0);
}

TEST(HandMapping, ValuesBeyondALimitAreClampedAndCounted) {
  // Roll 1.8 > 1.5 (roll clamped, and tilt = 0.25 - 0.6 < -0.25 clamped); bend -0.1 < 0 clamped.
  const MappedPostures mapped = mapToJoints(angles({{1.8, -0.1, -0.1}, {0.3, 0.5, 0.5}}), mapping(), mappedHand());
  EXPECT_DOUBLE_EQ(mapped.postures(0, 0), 1.5);
  EXPECT_DOUBLE_EQ(mapped.postures(0, 1), -0.25);
  EXPECT_DOUBLE_EQ(mapped.postures(0, 2), 0.0);
  EXPECT_EQ(mapped.clampedValues, 3);
  EXPECT_EQ(mapped.clampedPerJoint, (std::vector<long long>{1, 1, 1, 0}));
  EXPECT_DOUBLE_EQ(mapped.postures(1, 2), 0.5);
}

TEST(HandMapping, RulesFollowTheRobotsJointOrder) {
  JointLimits reversed = mappedHand();
  std::reverse(reversed.begin(), reversed.end());
  const HandMapping m = mapping();
  const auto rules = rulesForJoints(m, reversed);
  EXPECT_EQ(rules.front()->joint, "spare");
  EXPECT_EQ(rules.back()->joint, "roll");
}

TEST(HandMapping, UnknownJointNamesTheMappingLine) {
  HandMapping m = mapping();
  m.rules[2].joint = "bent";
  test::expectInputError([&] { rulesForJoints(m, mappedHand()); }, "map.yaml", "line 5 (joint bent)",
                         "unknown joint 'bent'");
}

TEST(HandMapping, EveryRobotJointNeedsExactlyOneRule) {
  HandMapping m = mapping();
  m.rules.pop_back();
  test::expectInputError([&] { rulesForJoints(m, mappedHand()); }, "map.yaml", "joints",
                         "no rule for the robot's hand joint spare");
  m = mapping();
  m.rules.push_back({"roll", {}, 0.1, 9});
  test::expectInputError([&] { rulesForJoints(m, mappedHand()); }, "map.yaml", "line 9",
                         "a second rule for joint roll");
}

TEST(HandMapping, ConstantOutsideTheLimitsIsAnError) {
  HandMapping m = mapping();
  m.rules[3].offset = 0.5;
  test::expectInputError([&] { rulesForJoints(m, mappedHand()); }, "map.yaml", "line 6 (joint spare)",
                         "outside the joint's limits");
}

}  // namespace
}  // namespace pmdplan
