#include "pmdplan/io/viewer/path_timeline.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace pmdplan {
namespace {

class PathTimelineTest : public ::testing::Test {
 protected:
  RobotModel robot_ = RobotModel::loadBuiltIn("sah_tx90");
  Configuration lowest() const {
    Configuration q(robot_.dof());
    for (int j = 0; j < robot_.dof(); ++j) q[j] = robot_.activeJoints()[static_cast<std::size_t>(j)].lower;
    return q;
  }
  Configuration highest() const {
    Configuration q(robot_.dof());
    for (int j = 0; j < robot_.dof(); ++j) q[j] = robot_.activeJoints()[static_cast<std::size_t>(j)].upper;
    return q;
  }
  double normalisedStep(const Configuration& a, const Configuration& b) const {
    return (robot_.normalise(b) - robot_.normalise(a)).norm();
  }
};

TEST_F(PathTimelineTest, KeepsEveryWaypointExactlyAndSpacesTheStatesEvenly) {
  const Configuration a = lowest(), c = highest();
  const Configuration b = 0.5 * (a + c);
  const PathTimeline timeline = pathTimeline({a, b, c}, robot_, {.stateSpacing = 0.05});
  ASSERT_EQ(timeline.waypointStates.size(), 3u);
  EXPECT_EQ(timeline.states[static_cast<std::size_t>(timeline.waypointStates[0])], a);
  EXPECT_EQ(timeline.states[static_cast<std::size_t>(timeline.waypointStates[1])], b);
  EXPECT_EQ(timeline.states[static_cast<std::size_t>(timeline.waypointStates[2])], c);
  EXPECT_EQ(timeline.waypointStates.back(), static_cast<int>(timeline.states.size()) - 1);
  // Each half is sqrt(19)/2 = 2.18 long: ceil(2.18 / 0.05) = 44 steps per half.
  EXPECT_EQ(timeline.waypointStates[1], 44);
  EXPECT_EQ(timeline.states.size(), 89u);
  for (std::size_t i = 1; i < timeline.states.size(); ++i) {
    EXPECT_LE(normalisedStep(timeline.states[i - 1], timeline.states[i]), 0.05 + 1e-12) << i;
    EXPECT_GT(normalisedStep(timeline.states[i - 1], timeline.states[i]), 0.04) << i;
  }
}

TEST_F(PathTimelineTest, ASegmentShorterThanTheSpacingIsOneStepAndAOnePointPathOneState) {
  const Configuration a = lowest();
  Configuration b = a;
  b[0] += 1e-6;
  const PathTimeline timeline = pathTimeline({a, b}, robot_);
  EXPECT_EQ(timeline.states.size(), 2u);
  EXPECT_EQ(timeline.waypointStates, (std::vector<int>{0, 1}));
  EXPECT_EQ(pathTimeline({a}, robot_).states.size(), 1u);
}

TEST_F(PathTimelineTest, RejectsWhatCannotBeATimeline) {
  EXPECT_THROW(pathTimeline({}, robot_), std::invalid_argument);
  EXPECT_THROW(pathTimeline({lowest()}, robot_, {.stateSpacing = 0.0}), std::invalid_argument);
  EXPECT_THROW(pathTimeline({Configuration::Zero(3)}, robot_), std::invalid_argument);
}

}  // namespace
}  // namespace pmdplan
