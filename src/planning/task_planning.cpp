#include "pmdplan/planning/task_planning.hpp"

#include <chrono>
#include <memory>

#include "pmdplan/planning/path_smoothing.hpp"
#include "pmdplan/planning/robot_planning_space.hpp"

namespace pmdplan {

TaskApproach taskApproach(const Task& task, CollisionChecking& checking, const GraspSettings& settings) {
  const auto began = std::chrono::steady_clock::now();
  TaskApproach approach;
  approach.grasp = graspApproach(task, checking.exact(), checking.tolerance(), settings);
  if (approach.grasp)
    approach.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return approach;
}

std::optional<std::size_t> appendClosing(const Task& task, const TaskApproach& approach,
                                         std::vector<Configuration>& path) {
  if (!approach.grasp) return std::nullopt;
  path.push_back(task.goal);
  return path.size() - 2;
}

TaskPlanningResult planTask(const Task& task, CollisionChecking& checking, const TaskPlanningSettings& options,
                            ProgressCallback progress) {
  const PlannerEntry& entry = options.planner ? *options.planner : ourPlanners().at("pmd");
  const PlanningSpace space = planningSpaceFromRobot(*task.robot);
  options.parameters.check();
  const std::unique_ptr<Planner> planner =
      entry.allocate({space, checking.states(), checking.motions(), options.parameters, options.synergies});
  TaskPlanningResult result;
  // A start in collision is reported as the planner reports it, before the goal is examined as
  // a grasp (which refuses a goal in contact with anything but the target).
  if (!checking.states().isValid(task.start)) {
    result.status = result.statistics.status = PlannerStatus::InvalidStart;
    result.statistics.stateChecks = 1;
    return result;
  }
  const TaskApproach approach = taskApproach(task, checking, options.grasp);
  result.grasp = approach.grasp;
  planner->setStartAndGoal(task.start, approach.end(task));
  if (progress) planner->setProgressCallback(std::move(progress));
  result.status = planner->solve();
  result.path = planner->path();
  result.statistics = planner->statistics();
  // Finding the pre-grasp is part of solving the task.
  result.statistics.planningTime += approach.seconds;
  if (result.statistics.solved()) result.closingFrom = appendClosing(task, approach, result.path);
  if (result.closingFrom) {
    result.statistics.pathNodes = result.path.size();
    result.statistics.pathLength = pathLength(result.path, space);
  }
  return result;
}

}  // namespace pmdplan
