#pragma once
// A task whose goal grasps its target as grasp planners give it: can_on_table with the goal can
// widened about its own axis until the published goal hand sinks `depth` into it (nothing else
// moves, so the hand touches the can and nothing else).
#include <variant>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan::test {

/// The widened radius of can_on_table's goal can (m).
inline double graspedCanRadius(double depth) {
  const Task task = loadTaskByName("can_on_table");
  ExactCollisionChecker checker(task);
  const double clearance = checker.clearance(task.goal, "goal_can")->metres;
  return std::get<CylinderShape>(task.findObstacle("goal_can")->shape).radius + clearance + depth;
}

inline Task graspingTask(double depth) {
  Task task = loadTaskByName("can_on_table");
  const double radius = graspedCanRadius(depth);
  for (Obstacle& obstacle : task.obstacles)
    if (obstacle.name == "goal_can") std::get<CylinderShape>(obstacle.shape).radius = radius;
  return task;
}

}  // namespace pmdplan::test
