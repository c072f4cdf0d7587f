#include "pmdplan/planning/task_planning.hpp"

#include "pmdplan/planning/robot_planning_space.hpp"

namespace pmdplan {

TaskPlanningResult planTask(const Task& task, CollisionChecking& checking, const TaskPlanningOptions& options,
                            ProgressCallback progress) {
  const PlanningSpace space = planningSpaceFromRobot(*task.robot);
  options.parameters.check();
  auto sampler = makeHandSampler(options.mode, space, options.synergies, options.parameters.pmdBox);
  PmdRoadmapPlanner planner(space, checking.states(), checking.motions(), std::move(sampler), options.parameters);
  planner.setStartAndGoal(task.start, task.goal);
  if (progress) planner.setProgressCallback(std::move(progress));
  TaskPlanningResult result;
  result.status = planner.solve();
  result.path = planner.path();
  result.statistics = planner.statistics();
  return result;
}

}  // namespace pmdplan
