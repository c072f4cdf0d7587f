#pragma once
// The grasp rule's contact part (docs/grasp_goals.md): which links are the hand's (the palm and
// every link below it) and which obstacle is the task's target. While the hand closes on the
// target (the closing phase of a path) contact between a hand link and the target is allowed, like
// MoveIt's allowed collision matrix during a grasp. Where the rule applies, and what it decides
// for states, goals and paths, is grasp_rule.hpp's.
#include <set>
#include <string>

#include "pmdplan/collision/collision_report.hpp"
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
  /// The pairs of `report` the rule allows (still sorted).
  CollisionReport allowed(const CollisionReport& report) const;

 private:
  std::string target_;
  std::set<std::string> handLinks_;
};

}  // namespace pmdplan
