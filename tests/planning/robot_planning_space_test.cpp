#include "pmdplan/planning/robot_planning_space.hpp"

#include <gtest/gtest.h>

#include "pmdplan/planning/synergy_hand_sampler.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"

namespace pmdplan {
namespace {

// The shipped robot and synergy model must fit together: the PMD sampler accepts exactly the
// robot's hand joints (the coupled distal joints are derived, not planned).
TEST(RobotPlanningSpace, TheShippedRobotAndSynergyModelFit) {
  const RobotModel robot = RobotModel::loadBuiltIn("sah_tx90");
  const PlanningSpace space = planningSpaceFromRobot(robot);
  EXPECT_EQ(space.dof(), robot.dof());
  EXPECT_EQ(space.armIndices.size(), 6u);
  EXPECT_EQ(space.handIndices.size(), 13u);
  EXPECT_EQ(space.jointNames(), robot.activeJointNames());

  const SynergyModel model = loadSynergyModel(defaultSynergyModelPath("sah_tx90"));
  const SynergyHandSampler sampler(space, model);
  EXPECT_EQ(sampler.initialDimension(), 2) << "thumb base + PMD 1";
  EXPECT_EQ(sampler.maxDimension(), 5) << "thumb base + 4 PMDs, as in the paper";

  UnitPoints random(SampleSequence::Random, 1, {sampler.maxDimension(), 0, 0});
  Configuration q = Eigen::VectorXd::Zero(space.dof());
  for (int i = 0; i < 200; ++i) {
    sampler.sample(2 + i % 4, random, q);
    ASSERT_TRUE(space.withinLimits(q, 0.0)) << "sample " << i;
    EXPECT_TRUE(robot.withinLimits(q)) << "sample " << i;
  }
}

}  // namespace
}  // namespace pmdplan
