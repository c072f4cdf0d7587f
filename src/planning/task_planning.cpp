#include "pmdplan/planning/task_planning.hpp"

#include <chrono>

#include "pmdplan/planning/lazy_pmd_planner.hpp"
#include "pmdplan/planning/path_smoothing.hpp"
#include "pmdplan/planning/pmd_connect_planner.hpp"
#include "pmdplan/planning/robot_planning_space.hpp"

namespace pmdplan {

TaskPlanningResult planTask(const Task& task, CollisionChecking& checking, const TaskPlanningOptions& options,
                            ProgressCallback progress) {
  const PlanningSpace space = planningSpaceFromRobot(*task.robot);
  options.parameters.check();
  auto sampler = makeHandSampler(options.mode, space, options.synergies, options.parameters.pmdBox);
  TaskPlanningResult result;
  // A start in collision is reported as the planner reports it, before the goal is examined as
  // a grasp (which refuses a goal in contact with anything but the target).
  if (!checking.states().isValid(task.start)) {
    result.status = result.statistics.status = PlannerStatus::InvalidStart;
    result.statistics.stateChecks = 1;
    return result;
  }
  const auto began = std::chrono::steady_clock::now();
  result.grasp = graspApproach(task, checking.exact(), checking.tolerance(), options.grasp);
  const double graspSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  const Configuration& approachGoal = result.grasp ? result.grasp->pregrasp : task.goal;
  if (options.algorithm == RoadmapAlgorithm::Lazy) {
    LazyPmdPlanner planner(space, checking.states(), checking.motions(), std::move(sampler), options.parameters);
    planner.setStartAndGoal(task.start, approachGoal);
    result.status = planner.solve();
    result.path = planner.path();
    result.statistics = planner.statistics();
  } else if (options.algorithm == RoadmapAlgorithm::Connect) {
    PmdConnectPlanner planner(space, checking.states(), checking.motions(), std::move(sampler), options.parameters);
    planner.setStartAndGoal(task.start, approachGoal);
    result.status = planner.solve();
    result.path = planner.path();
    result.statistics = planner.statistics();
  } else {
    PmdRoadmapPlanner planner(space, checking.states(), checking.motions(), std::move(sampler), options.parameters);
    planner.setStartAndGoal(task.start, approachGoal);
    if (progress) planner.setProgressCallback(std::move(progress));
    result.status = planner.solve();
    result.path = planner.path();
    result.statistics = planner.statistics();
  }
  // Finding the pre-grasp is part of solving the task.
  if (result.grasp) result.statistics.planningTime += graspSeconds;
  if (result.grasp && result.statistics.solved()) {
    result.closingFrom = result.path.size() - 1;
    result.path.push_back(task.goal);
    result.statistics.pathNodes = result.path.size();
    result.statistics.pathLength = pathLength(result.path, space);
  }
  return result;
}

}  // namespace pmdplan
