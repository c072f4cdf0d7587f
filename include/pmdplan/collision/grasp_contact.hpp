#pragma once
// The grasp rule (docs/grasp_goals.md): a task's goal may touch the task's target, and only with
// the hand. While the hand closes on the target (the closing phase of a path) contact between a
// hand link (the palm and every link below it) and the target is allowed, like MoveIt's allowed
// collision matrix during a grasp; every other pair counts as always, the target included for
// arm links.
#include <set>
#include <string>

#include "pmdplan/collision/collision_report.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

class GraspContactRule {
 public:
  /// Throws InputError naming the task file and `target` when the task has no target, and the
  /// robot's URDF and `end_effector` when the robot names no palm link.
  explicit GraspContactRule(const Task& task);

  const std::string& target() const { return target_; }
  bool isHandLink(const std::string& link) const { return handLinks_.count(link) != 0; }
  /// A hand link with the target.
  bool allows(const CollisionPair& pair) const;
  /// The pairs of `report` the rule does not allow (still sorted).
  CollisionReport forbidden(const CollisionReport& report) const;

 private:
  std::string target_;
  std::set<std::string> handLinks_;
};

enum class GoalContact {
  Free,          ///< touches nothing: plan to it directly
  GraspsTarget,  ///< only hand links touch, and only the target: approach, then close
  Refused,       ///< touches something else (or the task has no target)
};

struct GoalContactReport {
  GoalContact contact = GoalContact::Free;
  CollisionReport pairs;  ///< the hand-target pairs (GraspsTarget) or the pairs the rule forbids (Refused)
};

GoalContactReport classifyGoal(ExactCollisionChecker& checker, const Task& task);

/// classifyGoal that refuses: throws InputError(task file, "goal") naming the pairs when the goal
/// touches anything but the target with the hand.
GoalContact requirePlannableGoal(ExactCollisionChecker& checker, const Task& task);

}  // namespace pmdplan
