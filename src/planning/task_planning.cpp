#include "pmdplan/planning/task_planning.hpp"

#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/planning/robot_planning_space.hpp"

namespace pmdplan {

TaskPlanningResult planTask(const Task& task, ExactCollisionChecker& checker, const TaskPlanningOptions& options,
                            ProgressCallback progress) {
  const PlanningSpace space = planningSpaceFromRobot(*task.robot);
  auto sampler = makeHandSampler(options.mode, space, options.synergies);
  options.parameters.check();
  SegmentChecker segments(checker, *task.robot, options.toleranceMetres);
  PmdRoadmapPlanner planner(space, checker, segments, std::move(sampler), options.parameters);
  planner.setStartAndGoal(task.start, task.goal);
  if (progress) planner.setProgressCallback(std::move(progress));
  TaskPlanningResult result;
  result.status = planner.solve();
  result.path = planner.path();
  result.statistics = planner.statistics();
  return result;
}

}  // namespace pmdplan
