#pragma once
// Grasps as goals (docs/grasp_goals.md): when a task's goal grasps its target (only hand links
// touch it), the planner plans to a pre-grasp that clears the target and then closes the hand on
// the target along one straight segment, with hand-target contact allowed (grasp_rule.hpp).
// The pre-grasp is the task's `pregrasp:` or, without one, the goal with its hand opened.
// examineGoal is `plan`'s whole verdict on a goal, which `check` reports and `bench` relies on.
#include <optional>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

struct GraspSettings {
  /// How far a derived pre-grasp keeps the robot from the target (m): 5 mm, five times the default
  /// motion tolerance, so the approach ends visibly apart from the object.
  double clearance = 0.005;
  /// The opening search's step, as a fraction of the way from the goal hand to the open hand.
  double openingStep = 0.02;

  /// Throws InputError (field "grasp-clearance-mm" or "opening-step", no file) for values outside
  /// clearance >= 0 and 0 < step <= 1.
  void check() const;
};

struct GraspApproach {
  Configuration pregrasp;
  bool derived = false;    ///< opened from the goal (false: the task's pregrasp)
  double opening = 0.0;    ///< fraction of the way to the open hand (derived only)
  double clearance = 0.0;  ///< the robot's distance from the target at the pre-grasp (m)
};

/// `goal` with its hand fully open: every hand joint at its lower limit (the positive-flexion
/// convention: straight fingers, the thumb out of opposition), except joints whose range is
/// centred on zero (abductions), which go to zero.
Configuration openHand(const RobotModel& model, const Configuration& goal);

/// What `plan` makes of a task's goal: its contacts (GraspRule::judgeGoal), a grasp goal's
/// pre-grasp, or why it refuses the goal.
struct GoalExamination {
  GoalContactReport contact;
  std::optional<GraspApproach> approach;  ///< set for a grasp goal whose pre-grasp serves
  /// Set when plan refuses: field "goal" (contact the rule forbids, or no opening serves) or
  /// "pregrasp" (the task's pre-grasp does not serve).
  std::optional<PlanRefusal> refusal;
};

/// The goal examined as graspApproach does, refusals returned rather than thrown. Throws
/// InputError for bad settings and, as GraspRule::contact() does, for a robot without a palm link.
GoalExamination examineGoal(const Task& task, ExactCollisionChecker& checker, double tolerance,
                            const GraspSettings& settings = {});

/// examineGoal that refuses: nullopt when the goal touches nothing. When it grasps the target:
/// the task's pregrasp, checked, or the first opening (steps of `settings.openingStep` toward
/// openHand) that is free, clears the target by `settings.clearance` and closes onto the goal under
/// the grasp rule, the closing segment checked at `tolerance` (m). Throws InputError naming the
/// task file and `goal` when the goal touches anything else, `pregrasp` when the given pre-grasp
/// does not serve, or `goal` when no opening does.
std::optional<GraspApproach> graspApproach(const Task& task, ExactCollisionChecker& checker, double tolerance,
                                           const GraspSettings& settings = {});

}  // namespace pmdplan
