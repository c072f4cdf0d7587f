// The paper's tasks on our model: forward kinematics against the published palm poses, valid
// starts and goals, straight segments that need a real plan, goal hands around their targets.
#include <gtest/gtest.h>

#include <cmath>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/world/task.hpp"
#include "support/paper_tasks.hpp"

namespace pmdplan {
namespace {

Eigen::Isometry3d palmPose(ExactCollisionChecker& checker, const Configuration& q) {
  return checker.kinematics().linkPoses(q)[static_cast<std::size_t>(checker.model().palmLink())];
}

struct PublishedPalm {
  std::string task;
  bool goal;
  Eigen::Vector3d position;  // m
  std::optional<Eigen::Vector3d> zAxis;
};

TEST(PublishedTasks, ForwardKinematicsReproducesThePublishedPalmPoses) {
  const std::vector<PublishedPalm> published = {
      {"can_on_table", false, {-0.260, 0.537, 0.731}, std::nullopt},
      {"can_on_table", true, {-0.367, 0.950, 0.606}, Eigen::Vector3d(-0.21, 0.98, -0.04)},
      {"cans_on_desk", false, {-0.260, 0.537, 0.731}, std::nullopt},
      {"cans_on_desk", true, {-0.367, 0.950, 0.606}, Eigen::Vector3d(-0.21, 0.98, -0.04)},
      {"can_in_box", false, {-0.152, 0.974, 0.896}, std::nullopt},
      {"can_in_box", true, {-0.474, 1.090, 0.773}, Eigen::Vector3d(0.27, 0.21, -0.94)},
      {"cans_in_shelf", true, {-0.440, 1.119, 0.621}, std::nullopt},
  };
  for (const auto& p : published) {
    const Task task = loadTaskByName(p.task);
    ExactCollisionChecker checker(task);
    const auto palm = palmPose(checker, p.goal ? task.goal : task.start);
    EXPECT_LT((palm.translation() - p.position).norm(), 0.005) << p.task << (p.goal ? " goal" : " start");
    if (p.zAxis) {
      const double angle = std::acos(std::clamp(palm.linear().col(2).dot(p.zAxis->normalized()), -1.0, 1.0));
      EXPECT_LT(angle, 3.0 * M_PI / 180.0) << p.task << " goal palm z axis";
    }
  }
}

class EveryTask : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryTask, StartAndGoalAreValidAndTheStraightSegmentIsNot) {
  const Task task = loadTaskByName(GetParam());
  ExactCollisionChecker checker(task);
  const auto start = checker.check(task.start);
  const auto goal = checker.check(task.goal);
  EXPECT_TRUE(start.free()) << (start.free() ? "" : start.pairs.front().first + " - " + start.pairs.front().second);
  EXPECT_TRUE(goal.free()) << (goal.free() ? "" : goal.pairs.front().first + " - " + goal.pairs.front().second);
  SegmentChecker segments(checker, *task.robot, 0.001);
  EXPECT_FALSE(segments.isValid(task.start, task.goal)) << "the straight segment needs no planning";
}

TEST_P(EveryTask, TheGoalHandSurroundsItsTarget) {
  const Task task = loadTaskByName(GetParam());
  ASSERT_TRUE(task.target) << "every paper task names the object its goal grasps";
  ExactCollisionChecker checker(task);
  const auto& model = *task.robot;
  std::vector<int> handLinks;
  for (std::size_t l = 0; l < model.links().size(); ++l)
    if (static_cast<int>(l) == model.palmLink() || model.links()[l].name.find("_link") != std::string::npos ||
        model.links()[l].name.find("_knuckle") != std::string::npos)
      if (model.links()[l].name.rfind("tx90", 0) != 0) handLinks.push_back(static_cast<int>(l));
  for (const std::string finger : {"thumb", "index", "middle", "ring"}) {
    const double d = checker.distanceToObstacle(task.goal, {model.linkIndex(finger + "_distal_link")}, *task.target);
    EXPECT_LT(d, 0.045) << finger << " fingertip is " << d * 1000 << " mm from " << *task.target;
  }
  const double closest = checker.distanceToObstacle(task.goal, handLinks, *task.target);
  EXPECT_LT(closest, 0.005) << "closest hand link is " << closest * 1000 << " mm from " << *task.target;
  EXPECT_GT(closest, 0.0) << "the goal hand touches its target";
}

INSTANTIATE_TEST_SUITE_P(PaperTasks, EveryTask, ::testing::ValuesIn(test::kPaperTasks));

}  // namespace
}  // namespace pmdplan
