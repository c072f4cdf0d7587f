#include "pmdplan/collision/grasp_rule.hpp"

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

void PlanRefusal::raise(const Task& task) const { throw InputError(task.file.string(), field, reason); }

GraspRule::GraspRule(const Task& task) : task_(task) {
  if (task.target && task.robot->palmLink() >= 0) contact_.emplace(task);
}

const GraspContactRule& GraspRule::contact() const {
  if (!contact_) (void)GraspContactRule(task_);  // no target or no palm link: throws, naming which
  return *contact_;
}

bool GraspRule::counts(const CollisionPair& pair, PathPhase phase) const {
  return phase == PathPhase::Approach || !contact_ || !contact_->allows(pair);
}

StateContacts GraspRule::judgeState(ExactCollisionChecker& checker, const Configuration& q, PathPhase phase) const {
  StateContacts result;
  CollisionReport report = checker.check(q);
  if (phase == PathPhase::Approach || !contact_) {
    result.collisions = std::move(report);
  } else {
    result.collisions = contact_->forbidden(report);
    result.allowed = contact_->allowed(report);
  }
  return result;
}

CollisionReport GraspRule::collisions(ExactCollisionChecker& checker, const Configuration& q, PathPhase phase) const {
  return judgeState(checker, q, phase).collisions;
}

std::optional<PlanRefusal> GraspRule::startRefusal(ExactCollisionChecker& checker) const {
  CollisionReport report = checker.check(task_.start);
  if (report.free()) return std::nullopt;
  return PlanRefusal{"start", "the start configuration is in collision: " + pairsText(report), std::move(report)};
}

GoalContactReport GraspRule::judgeGoal(ExactCollisionChecker& checker) const {
  GoalContactReport result;
  CollisionReport report = checker.check(task_.goal);
  if (report.free()) return result;
  std::string rule;
  if (!task_.target) {
    result.pairs = std::move(report);
    rule = "a goal may touch only the task's target, and the task names none";
  } else {
    const GraspContactRule& grasp = contact();
    CollisionReport forbidden = grasp.forbidden(report);
    if (forbidden.free()) {
      result.contact = GoalContact::GraspsTarget;
      result.pairs = std::move(report);
      return result;
    }
    result.pairs = std::move(forbidden);
    rule = "only hand links may touch, and only the target '" + grasp.target() + "'";
  }
  result.contact = GoalContact::Refused;
  result.refusal = PlanRefusal{
      "goal", "the goal configuration is in collision: " + pairsText(result.pairs) + " (" + rule + ")", result.pairs};
  return result;
}

PathValidation GraspRule::validatePath(ExactCollisionChecker& checker, const SegmentChecker& segments,
                                       const std::vector<Configuration>& path, const PathPhases& phases) const {
  if (!phases.closingFrom) return pmdplan::validatePath(checker, segments, path, task_.start, task_.goal);
  if (!task_.target) {
    PathValidation result;
    result.valid = false;
    result.problems.push_back("the path has a closing phase, but the task names no target that the hand may touch");
    return result;
  }
  return pmdplan::validatePath(checker, segments, path, task_.start, task_.goal,
                               ClosingPhase{*phases.closingFrom, &contact()});
}

}  // namespace pmdplan
