#include "pmdplan/planning/grasp_approach.hpp"

#include <cmath>
#include <cstdio>

#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

std::string millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f mm", 1000.0 * metres);
  return text;
}

/// Why `pregrasp` cannot start the closing (the reason and its pairs), or nothing when it can.
std::optional<PlanRefusal> closingProblem(const Task& task, ExactCollisionChecker& checker,
                                          const SegmentChecker& segments, const GraspRule& rule,
                                          const Configuration& pregrasp) {
  CollisionReport atPregrasp = checker.check(pregrasp);
  if (!atPregrasp.free())
    return PlanRefusal{"pregrasp", "it is in collision: " + pairsText(atPregrasp), std::move(atPregrasp)};
  auto closing = segments.inspect(
      [&](const Configuration& q) { return rule.collisions(checker, q, PathPhase::Closing); }, pregrasp, task.goal);
  if (closing.free) return std::nullopt;
  char where[64];
  std::snprintf(where, sizeof where, "closing onto the goal collides at %.1f %%: ", 100.0 * *closing.firstCollision);
  return PlanRefusal{"pregrasp", where + pairsText(closing.collisions), std::move(closing.collisions)};
}

}  // namespace

void GraspSettings::check() const {
  if (!(clearance >= 0.0) || !std::isfinite(clearance))
    throw InputError("", "grasp-clearance-mm", "expected a clearance of at least 0 mm");
  if (!(openingStep > 0.0 && openingStep <= 1.0)) throw InputError("", "opening-step", "expected a fraction in (0, 1]");
}

Configuration openHand(const RobotModel& model, const Configuration& goal) {
  Configuration open = goal;
  for (int i : model.group("hand")) {
    const auto& joint = model.activeJoints()[static_cast<std::size_t>(i)];
    open[i] = std::abs(joint.lower + joint.upper) < 1e-9 ? 0.0 : joint.lower;
  }
  return open;
}

GoalExamination examineGoal(const Task& task, ExactCollisionChecker& checker, double tolerance,
                            const GraspSettings& settings) {
  settings.check();
  const GraspRule rule(task);
  GoalExamination result;
  result.contact = rule.judgeGoal(checker);
  if (result.contact.contact != GoalContact::GraspsTarget) {
    result.refusal = result.contact.refusal;
    return result;
  }
  const std::string& target = rule.contact().target();
  const SegmentChecker segments(checker, *task.robot, tolerance);
  if (task.pregrasp) {
    if (auto problem = closingProblem(task, checker, segments, rule, *task.pregrasp)) {
      problem->reason = "the pre-grasp cannot start the closing onto the goal: " + problem->reason;
      result.refusal = std::move(problem);
    } else {
      result.approach = GraspApproach{*task.pregrasp, false, 0.0, checker.clearance(*task.pregrasp, target)->metres};
    }
    return result;
  }
  const Configuration open = openHand(*task.robot, task.goal);
  const int steps = static_cast<int>(std::ceil(1.0 / settings.openingStep - 1e-9));
  for (int s = 1; s <= steps; ++s) {
    const double t = std::min(1.0, s * settings.openingStep);
    const Configuration q = task.goal + t * (open - task.goal);
    const double clearance = checker.clearance(q, target)->metres;
    if (clearance < settings.clearance) continue;
    if (!closingProblem(task, checker, segments, rule, q)) {
      result.approach = GraspApproach{q, true, t, clearance};
      return result;
    }
  }
  result.refusal = PlanRefusal{"goal",
                               "the goal grasps the target '" + target + "', but no opening of its hand clears the " +
                                   "target by " + millimetres(settings.clearance) +
                                   " and closes onto the goal without other contact; give a pre-grasp " +
                                   "(pregrasp: {joints_deg: {...}}) in the task file",
                               {}};
  return result;
}

std::optional<GraspApproach> graspApproach(const Task& task, ExactCollisionChecker& checker, double tolerance,
                                           const GraspSettings& settings) {
  GoalExamination examined = examineGoal(task, checker, tolerance, settings);
  if (examined.refusal) examined.refusal->raise(task);
  return examined.approach;
}

}  // namespace pmdplan
