#include "pmdplan/planning/robot_planning_space.hpp"

#include <stdexcept>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

PlanningSpace planningSpaceFromRobot(const RobotModel& model) {
  const std::string file = model.urdfPath().string();
  if (!model.hasGroup("hand"))
    throw InputError(file, "groups",
                     "the robot has no \"hand\" group; the planner needs a \"hand\" group (and an \"arm\" group "
                     "unless the robot is a hand alone): write them with `pmdplan robot init " +
                         file + " --arm J1,J2,... --palm LINK`");
  PlanningSpace space;
  space.joints = model.activeJoints();
  if (model.hasGroup("arm")) space.armIndices = model.group("arm");
  space.handIndices = model.group("hand");
  try {
    space.check();
  } catch (const std::invalid_argument& error) {
    throw InputError(file, "groups", error.what());
  }
  return space;
}

}  // namespace pmdplan
