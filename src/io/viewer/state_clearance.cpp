#include "pmdplan/io/viewer/state_clearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pmdplan/collision/exact_collision_checker.hpp"

namespace pmdplan {
namespace {

/// Links with geometry that some joint moves.
std::vector<int> movingLinks(const RobotModel& robot) {
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
  return moving;
}

/// The robot links among the pairs' names, each once, in the pairs' order.
std::vector<std::string> linksOf(const CollisionReport& report, const RobotModel& robot) {
  std::vector<std::string> links;
  for (const auto& [a, b] : report.pairs)
    for (const std::string& name : {a, b})
      if (robot.linkIndex(name) >= 0 && std::find(links.begin(), links.end(), name) == links.end())
        links.push_back(name);
  return links;
}

}  // namespace

std::vector<StateClearance> stateClearances(const Task& task, const std::vector<Configuration>& states,
                                            const PathPhases& phases) {
  const RobotModel& robot = *task.robot;
  ExactCollisionChecker checker(task);
  const GraspRule rule(task);
  const std::vector<int> moving = movingLinks(robot);
  // Per phase and obstacle, the moving links whose distance to it counts.
  std::vector<std::vector<int>> counted[2];
  for (const PathPhase phase : {PathPhase::Approach, PathPhase::Closing})
    for (const Obstacle& obstacle : task.obstacles) {
      std::vector<int> links;
      for (const int link : moving)
        if (rule.counts({robot.links()[static_cast<std::size_t>(link)].name, obstacle.name}, phase))
          links.push_back(link);
      counted[static_cast<int>(phase)].push_back(std::move(links));
    }
  std::vector<StateClearance> result;
  for (std::size_t s = 0; s < states.size(); ++s) {
    const Configuration& q = states[s];
    const PathPhase phase = phases.point(s);
    StateClearance state;
    state.clearance = std::numeric_limits<double>::infinity();
    for (std::size_t o = 0; o < task.obstacles.size(); ++o) {
      const std::vector<int>& links = counted[static_cast<int>(phase)][o];
      if (links.empty()) continue;
      const std::string& obstacle = task.obstacles[o].name;
      double distance = checker.distanceToObstacle(q, links, obstacle);
      // Overlapping, FCL's distance says -1 m: the penetration depth instead (FCL's signed
      // distance over every link), or 0 where that would include allowed grasp contact.
      if (distance < 0.0)
        distance = links.size() == counted[static_cast<int>(PathPhase::Approach)][o].size()
                       ? std::min(0.0, checker.clearance(q, obstacle)->metres)
                       : 0.0;
      state.clearance = std::min(state.clearance, distance);
    }
    const StateContacts contacts = rule.judgeState(checker, q, phase);
    state.collidingLinks = linksOf(contacts.collisions, robot);
    state.contactLinks = linksOf(contacts.allowed, robot);
    if (std::isinf(state.clearance)) state.clearance = 0.0;  // no obstacle to measure from
    result.push_back(std::move(state));
  }
  return result;
}

}  // namespace pmdplan
