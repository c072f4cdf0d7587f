#include "pmdplan/io/viewer/state_clearance.hpp"

#include <algorithm>
#include <limits>

#include "pmdplan/collision/exact_collision_checker.hpp"

namespace pmdplan {

std::vector<StateClearance> stateClearances(const Task& task, const std::vector<Configuration>& states) {
  const RobotModel& robot = *task.robot;
  ExactCollisionChecker checker(task);
  std::vector<int> moving;
  for (int link = 0; link < static_cast<int>(robot.links().size()); ++link) {
    bool moves = false;
    for (int joint = robot.links()[static_cast<std::size_t>(link)].parentJoint; joint >= 0 && !moves;) {
      const Joint& j = robot.joints()[static_cast<std::size_t>(joint)];
      moves = j.type != JointType::Fixed;
      joint = robot.links()[static_cast<std::size_t>(j.parentLink)].parentJoint;
    }
    if (moves && !robot.links()[static_cast<std::size_t>(link)].collisionShapes.empty()) moving.push_back(link);
  }
  std::vector<std::string> linkNames;
  for (const Link& link : robot.links()) linkNames.push_back(link.name);
  std::vector<StateClearance> result;
  for (const Configuration& q : states) {
    StateClearance state;
    state.clearance = std::numeric_limits<double>::infinity();
    for (const auto& obstacle : task.obstacles)
      state.clearance = std::min(state.clearance, checker.distanceToObstacle(q, moving, obstacle.name));
    for (const auto& [a, b] : checker.check(q).pairs)
      for (const std::string& name : {a, b})
        if (std::find(linkNames.begin(), linkNames.end(), name) != linkNames.end() &&
            std::find(state.collidingLinks.begin(), state.collidingLinks.end(), name) == state.collidingLinks.end())
          state.collidingLinks.push_back(name);
    if (task.obstacles.empty()) state.clearance = 0.0;
    result.push_back(std::move(state));
  }
  return result;
}

}  // namespace pmdplan
