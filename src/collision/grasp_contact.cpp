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

GoalContactReport classifyGoal(ExactCollisionChecker& checker, const Task& task) {
  GoalContactReport result;
  CollisionReport report = checker.check(task.goal);
  if (report.free()) return result;
  if (!task.target) {
    result.contact = GoalContact::Refused;
    result.pairs = std::move(report);
    return result;
  }
  const GraspContactRule rule(task);
  CollisionReport forbidden = rule.forbidden(report);
  if (forbidden.free()) {
    result.contact = GoalContact::GraspsTarget;
    result.pairs = std::move(report);
  } else {
    result.contact = GoalContact::Refused;
    result.pairs = std::move(forbidden);
  }
  return result;
}

GoalContact requirePlannableGoal(ExactCollisionChecker& checker, const Task& task) {
  const GoalContactReport goal = classifyGoal(checker, task);
  if (goal.contact != GoalContact::Refused) return goal.contact;
  const std::string rule = task.target ? "only hand links may touch, and only the target '" + *task.target + "'"
                                       : "a goal may touch only the task's target, and the task names none";
  throw InputError(task.file.string(), "goal",
                   "the goal configuration is in collision: " + pairsText(goal.pairs) + " (" + rule + ")");
}

}  // namespace pmdplan
