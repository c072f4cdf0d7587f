#include "pmdplan/io/files/task_check_json.hpp"

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/collision/path_validation.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

nlohmann::json checkedPairsJson(const CollisionReport& report) {
  auto pairs = nlohmann::json::array();
  for (const auto& [a, b] : report.pairs) pairs.push_back({a, b});
  return pairs;
}

nlohmann::json checkedVectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json checkedConfigurationJson(ExactCollisionChecker& checker, const Configuration& q) {
  const auto report = checker.check(q);
  const auto& model = checker.model();
  if (model.palmLink() < 0)
    throw InputError(model.urdfPath().string(), "end_effector",
                     "the robot names no palm link; write its SRDF with `pmdplan robot init " +
                         model.urdfPath().string() + " --arm J1,J2,... --palm LINK [--hand J1,...]`");
  const Eigen::Isometry3d palm = checker.kinematics().linkPoses(q)[static_cast<std::size_t>(model.palmLink())];
  const auto clearance = checker.clearance(q);
  return {{"valid", report.free()},
          {"collisions", checkedPairsJson(report)},
          {"clearance_mm", clearance ? nlohmann::json(1000.0 * clearance->metres) : nlohmann::json()},
          {"nearest", clearance ? nlohmann::json{clearance->pair.first, clearance->pair.second} : nlohmann::json()},
          {"palm_position", checkedVectorJson(palm.translation())},
          {"palm_z_axis", checkedVectorJson(palm.linear().col(2))}};
}

/// What plan will make of the task: the refusals (start, goal or pre-grasp), and on the goal a
/// grasp's target and pre-grasp.
nlohmann::json planVerdictJson(ExactCollisionChecker& checker, const Task& task, double tolerance,
                               const GraspSettings& grasp, nlohmann::json& goal) {
  auto refusals = nlohmann::json::array();
  const auto add = [&](const PlanRefusal& refusal) {
    refusals.push_back(
        {{"field", refusal.field}, {"reason", refusal.reason}, {"pairs", checkedPairsJson(refusal.pairs)}});
  };
  if (const auto start = GraspRule(task).startRefusal(checker)) add(*start);
  const GoalExamination examined = examineGoal(task, checker, tolerance, grasp);
  if (examined.contact.contact == GoalContact::GraspsTarget) goal["grasp"] = *task.target;
  if (const auto& a = examined.approach)
    goal["pregrasp"] = {{"derived", a->derived}, {"opening", a->opening}, {"clearance_mm", 1000.0 * a->clearance}};
  if (examined.refusal) add(*examined.refusal);
  return {{"accepts", refusals.empty()}, {"refusals", std::move(refusals)}};
}

}  // namespace

nlohmann::json taskCheckJson(const Task& task, double toleranceMm, const GraspSettings& grasp) {
  checkMotionToleranceMm(toleranceMm);
  ExactCollisionChecker checker(task);
  SegmentChecker segments(checker, *task.robot, toleranceMm / 1000.0);
  try {  // the straight segment's states, bounded as validate's (collision/path_validation.hpp)
    checkValidationWork(segments, {task.start, task.goal});
  } catch (const InputError& e) {
    throw InputError(task.file.string(), "start, goal", e.message());
  }
  const auto start = checkedConfigurationJson(checker, task.start);
  auto goal = checkedConfigurationJson(checker, task.goal);
  nlohmann::json plan = planVerdictJson(checker, task, toleranceMm / 1000.0, grasp, goal);
  const auto line = segments.inspect(checker, task.start, task.goal);
  nlohmann::json straight = {
      {"free", line.free},
      {"first_collision", line.firstCollision ? nlohmann::json(*line.firstCollision) : nlohmann::json()},
      {"collisions", checkedPairsJson(line.collisions)},
      {"states_checked", line.statesChecked},
      {"states_needed", line.statesNeeded},
      {"tolerance_mm", toleranceMm}};
  return {{"task", task.name},
          {"start", start},
          {"goal", std::move(goal)},
          {"straight_line", std::move(straight)},
          {"plan", std::move(plan)}};
}

}  // namespace pmdplan
