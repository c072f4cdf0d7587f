#pragma once
// The planning space of a robot model: its active joints and its "arm" and "hand" groups.
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/planning/planning_space.hpp"

namespace pmdplan {

/// Throws InputError naming the robot's file and "groups" if the model lacks a "hand" group or the
/// groups do not split the active joints. Without an "arm" group the robot is a hand alone.
PlanningSpace planningSpaceFromRobot(const RobotModel& model);

}  // namespace pmdplan
