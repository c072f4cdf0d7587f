#include "pmdplan/io/viewer/robot_mimic.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace pmdplan {
namespace {

TEST(RobotMimic, ListsTheCoupledDistalJointsOfTheShippedRobot) {
  const RobotModel robot = RobotModel::loadBuiltIn("sah_tx90");
  const std::vector<MimicRelation> relations = mimicRelations(robot);
  ASSERT_EQ(relations.size(), 4u) << "one distal joint per finger";
  const std::vector<std::string> active = robot.activeJointNames();
  for (const MimicRelation& relation : relations) {
    EXPECT_EQ(std::count(active.begin(), active.end(), relation.joint), 0) << relation.joint << " is derived";
    EXPECT_GE(robot.jointIndex(relation.source), 0);
    const Joint& joint = robot.joints()[static_cast<std::size_t>(robot.jointIndex(relation.joint))];
    EXPECT_EQ(relation.multiplier, joint.mimicMultiplier);
    EXPECT_EQ(relation.offset, joint.mimicOffset);
  }
  const auto indexDistal = std::find_if(relations.begin(), relations.end(),
                                        [](const MimicRelation& r) { return r.joint == "index_distal"; });
  ASSERT_NE(indexDistal, relations.end());
  EXPECT_EQ(indexDistal->source, "index_medium");
}

}  // namespace
}  // namespace pmdplan
