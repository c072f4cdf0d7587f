#include "pmdplan/planning/grasp_approach.hpp"

#include <cmath>
#include <cstdio>

#include "pmdplan/collision/grasp_contact.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

std::string millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f mm", 1000.0 * metres);
  return text;
}

/// Why `pregrasp` cannot start the closing, or "" when it can.
std::string closingProblem(const Task& task, ExactCollisionChecker& checker, const SegmentChecker& segments,
                           const GraspContactRule& rule, const Configuration& pregrasp) {
  const CollisionReport atPregrasp = checker.check(pregrasp);
  if (!atPregrasp.free()) return "it is in collision: " + pairsText(atPregrasp);
  const auto closing =
      segments.inspect([&](const Configuration& q) { return rule.forbidden(checker.check(q)); }, pregrasp, task.goal);
  if (!closing.free) {
    char where[64];
    std::snprintf(where, sizeof where, "closing onto the goal collides at %.1f %%: ", 100.0 * *closing.firstCollision);
    return where + pairsText(closing.collisions);
  }
  return "";
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

std::optional<GraspApproach> graspApproach(const Task& task, ExactCollisionChecker& checker, double tolerance,
                                           const GraspSettings& settings) {
  settings.check();
  if (requirePlannableGoal(checker, task) == GoalContact::Free) return std::nullopt;
  const GraspContactRule rule(task);
  const SegmentChecker segments(checker, *task.robot, tolerance);
  const std::string file = task.file.string();
  if (task.pregrasp) {
    const std::string problem = closingProblem(task, checker, segments, rule, *task.pregrasp);
    if (!problem.empty())
      throw InputError(file, "pregrasp", "the pre-grasp cannot start the closing onto the goal: " + problem);
    return GraspApproach{*task.pregrasp, false, 0.0, checker.clearance(*task.pregrasp, rule.target())->metres};
  }
  const Configuration open = openHand(*task.robot, task.goal);
  const int steps = static_cast<int>(std::ceil(1.0 / settings.openingStep - 1e-9));
  for (int s = 1; s <= steps; ++s) {
    const double t = std::min(1.0, s * settings.openingStep);
    const Configuration q = task.goal + t * (open - task.goal);
    const double clearance = checker.clearance(q, rule.target())->metres;
    if (clearance < settings.clearance) continue;
    if (closingProblem(task, checker, segments, rule, q).empty()) return GraspApproach{q, true, t, clearance};
  }
  throw InputError(file, "goal",
                   "the goal grasps the target '" + rule.target() +
                       "', but no opening of its hand clears the target by " + millimetres(settings.clearance) +
                       " and closes onto the goal without other contact; give a pre-grasp " +
                       "(pregrasp: {joints_deg: {...}}) in the task file");
}

}  // namespace pmdplan
