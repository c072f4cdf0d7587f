#include "pmdplan/planning/planning_space.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "planning/toy_problem.hpp"

namespace pmdplan {
namespace {

TEST(PlanningSpace, NormalisesByTheLimits) {
  const PlanningSpace space = toy::space();
  EXPECT_NO_THROW(space.check());
  Configuration q(6);
  q << -1.0, 2.0, 0.75, 0.5, 0.0, 0.9;
  const Eigen::VectorXd u = space.normalise(q);
  EXPECT_DOUBLE_EQ(u[0], 0.0);
  EXPECT_DOUBLE_EQ(u[1], 1.0);
  EXPECT_DOUBLE_EQ(u[2], 0.5);
  EXPECT_DOUBLE_EQ(u[3], 0.5);
  EXPECT_DOUBLE_EQ(u[4], 0.5);
  EXPECT_DOUBLE_EQ(u[5], 1.0);
  EXPECT_TRUE(space.denormalise(u).isApprox(q));
  EXPECT_EQ(space.indexOf("finger_b"), 4);
  EXPECT_EQ(space.indexOf("nope"), -1);
  EXPECT_EQ(space.jointNames().front(), "shoulder");
}

TEST(PlanningSpace, DistancesAreNormalised) {
  const PlanningSpace space = toy::space();
  const Configuration a = toy::fromUnit({0.1, 0.5, 0.3, 0.8, 0.8, 0.5});
  const Configuration b = toy::fromUnit({0.4, 0.9, 0.3, 0.8, 0.8, 0.5});
  EXPECT_NEAR(space.distance(a, b), 0.5, 1e-12);
  EXPECT_NEAR(space.armDistance(a, b), 0.5, 1e-12);
  const Configuration c = toy::fromUnit({0.1, 0.5, 0.3, 0.5, 0.4, 0.5});
  EXPECT_NEAR(space.distance(a, c), 0.5, 1e-12);
  EXPECT_NEAR(space.armDistance(a, c), 0.0, 1e-12);
  EXPECT_EQ(space.distance(a, c), space.distance(c, a));
}

TEST(PlanningSpace, WithinLimits) {
  const PlanningSpace space = toy::space();
  Configuration q = toy::start();
  EXPECT_TRUE(space.withinLimits(q));
  q[3] = 1.0 + 1e-6;
  EXPECT_FALSE(space.withinLimits(q));
  EXPECT_TRUE(space.withinLimits(q, 1e-5));
  EXPECT_FALSE(space.withinLimits(Eigen::VectorXd::Zero(2)));
}

TEST(PlanningSpace, CheckRejectsBadGroupsAndLimits) {
  PlanningSpace space = toy::space();
  space.handIndices = {2, 3, 4};
  EXPECT_THROW(space.check(), std::invalid_argument) << "joint 5 in no group";
  space = toy::space();
  space.handIndices = {1, 2, 3, 4, 5};
  EXPECT_THROW(space.check(), std::invalid_argument) << "joint 1 twice";
  space = toy::space();
  space.armIndices = {0, 1, 6};
  EXPECT_THROW(space.check(), std::invalid_argument) << "index out of range";
  space = toy::space();
  space.joints[2].upper = space.joints[2].lower;
  EXPECT_THROW(space.check(), std::invalid_argument) << "empty range";
  space = toy::space();
  space.armIndices = {0, 1, 2, 3, 4, 5};
  space.handIndices.clear();
  EXPECT_THROW(space.check(), std::invalid_argument) << "no hand";
}

TEST(PlanningSpace, AHandAloneHasNoArmJoints) {
  PlanningSpace space = toy::space();
  space.armIndices.clear();
  space.handIndices = {0, 1, 2, 3, 4, 5};
  EXPECT_NO_THROW(space.check());
  EXPECT_EQ(space.armDistance(space.denormalise(Eigen::VectorXd::Zero(6)), space.denormalise(Eigen::VectorXd::Ones(6))),
            0.0);
}

}  // namespace
}  // namespace pmdplan
