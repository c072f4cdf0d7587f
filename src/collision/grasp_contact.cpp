#include "pmdplan/collision/grasp_contact.hpp"

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

GraspContactRule::GraspContactRule(const Task& task) {
  if (!task.target)
    throw InputError(task.file.string(), "target",
                     "a grasp needs the task's target: the name of the obstacle the goal grasps");
  target_ = *task.target;
  const RobotModel& model = *task.robot;
  const int palm = model.palmLink();
  if (palm < 0)
    throw InputError(model.urdfPath().string(), "end_effector",
                     "the robot names no palm link, so no link is the hand's");
  for (std::size_t l = 0; l < model.links().size(); ++l)
    for (int link = static_cast<int>(l); link >= 0;) {
      if (link == palm) {
        handLinks_.insert(model.links()[l].name);
        break;
      }
      const int joint = model.links()[static_cast<std::size_t>(link)].parentJoint;
      link = joint < 0 ? -1 : model.joints()[static_cast<std::size_t>(joint)].parentLink;
    }
}

bool GraspContactRule::allows(const CollisionPair& pair) const {
  return pair.second == target_ && isHandLink(pair.first);
}

CollisionReport GraspContactRule::forbidden(const CollisionReport& report) const {
  CollisionReport result;
  for (const auto& pair : report.pairs)
    if (!allows(pair)) result.pairs.push_back(pair);
  return result;
}

CollisionReport GraspContactRule::allowed(const CollisionReport& report) const {
  CollisionReport result;
  for (const auto& pair : report.pairs)
    if (allows(pair)) result.pairs.push_back(pair);
  return result;
}

}  // namespace pmdplan
