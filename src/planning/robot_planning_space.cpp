#include "pmdplan/planning/robot_planning_space.hpp"

#include <stdexcept>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

PlanningSpace planningSpaceFromRobot(const RobotModel& model) {
  const std::string file = model.urdfPath().string();
  for (const char* group : {"arm", "hand"})
    if (!model.hasGroup(group))
      throw InputError(file, "groups", std::string("the robot has no \"") + group +
                                           "\" group; the planner needs an \"arm\" and a \"hand\" group");
  PlanningSpace space;
  space.joints = model.activeJoints();
  space.armIndices = model.group("arm");
  space.handIndices = model.group("hand");
  try {
    space.check();
  } catch (const std::invalid_argument& error) {
    throw InputError(file, "groups", error.what());
  }
  return space;
}

}  // namespace pmdplan
