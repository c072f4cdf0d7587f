// Self-collision of hand postures: human-like and published postures are free, a thumb pressed
// into the index finger is not.
#include <gtest/gtest.h>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {
namespace {

const std::vector<std::string> kTasks = {"can_on_table", "cans_on_desk", "can_in_box", "cans_in_shelf", "t_in_clutter"};

/// The robot alone in free space, so only self-collision can be reported.
Task robotAlone() {
  Task task;
  task.name = "self";
  task.robot = std::make_shared<RobotModel>(RobotModel::loadBuiltIn("sah_tx90"));
  return task;
}

Configuration withHand(const RobotModel& model, const std::vector<std::pair<std::string, double>>& degrees) {
  Configuration q = Configuration::Zero(model.dof());
  q[2] = M_PI / 2;  // elbow bent: the arm clear of the hand
  for (const auto& [name, value] : degrees) q[model.activeIndex(name)] = value * M_PI / 180.0;
  return q;
}

std::string describe(const CollisionReport& report) {
  std::string text;
  for (const auto& [a, b] : report.pairs) text += a + " - " + b + "; ";
  return text;
}

TEST(HandSelfCollision, AFullyOpenHandIsFree) {
  const Task task = robotAlone();
  ExactCollisionChecker checker(task);
  const auto& model = *task.robot;
  Configuration q = withHand(model, {});
  for (int i : model.group("hand")) {
    const auto& j = model.activeJoints()[static_cast<std::size_t>(i)];
    q[i] = j.name.find("abduction") != std::string::npos ? 0.0 : j.lower;  // flexion and thumb base at their open end
  }
  const auto report = checker.check(q);
  EXPECT_TRUE(report.free()) << describe(report);
}

TEST(HandSelfCollision, EveryPublishedStartAndGoalHandIsFree) {
  const Task alone = robotAlone();
  ExactCollisionChecker checker(alone);
  const auto& model = *alone.robot;
  for (const auto& name : kTasks) {
    const Task task = loadTaskByName(name);
    for (const auto* q : {&task.start, &task.goal}) {
      Configuration posture = withHand(model, {});
      for (int i : model.group("hand")) posture[i] = (*q)[i];
      const auto report = checker.check(posture);
      EXPECT_TRUE(report.free()) << name << ": " << describe(report);
    }
  }
}

TEST(HandSelfCollision, TheThumbDrivenIntoTheIndexFingerCollides) {
  const Task task = robotAlone();
  ExactCollisionChecker checker(task);
  const auto& model = *task.robot;
  // Thumb fully opposed and flexed across the palm while the index finger curls onto it.
  const Configuration q = withHand(model, {{"thumb_base", 90}, {"thumb_abduction", 15}, {"thumb_proximal", 60},
                                           {"thumb_medium", 40}, {"index_proximal", 75}, {"index_medium", 40}});
  const auto report = checker.check(q);
  ASSERT_FALSE(report.free());
  bool thumbIndex = false;
  for (const auto& [a, b] : report.pairs)
    thumbIndex |= (a.rfind("thumb", 0) == 0 && b.rfind("index", 0) == 0) || (a.rfind("index", 0) == 0 && b.rfind("thumb", 0) == 0);
  EXPECT_TRUE(thumbIndex) << describe(report);
}

}  // namespace
}  // namespace pmdplan
