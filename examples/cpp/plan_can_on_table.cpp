// Plans the built-in task can_on_table with the paper's planner through the installed library:
// load the task and the robot's shipped synergy model, build the fast collision checks, plan.
#include <cstdio>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/world/task.hpp"

int main() {
  using namespace pmdplan;
  const Task task = loadTaskByName("can_on_table");
  const SynergyModel synergies = loadSynergyModel(defaultSynergyModelPath(task.robot->name()));
  CollisionChecking checking(task, CheckerKind::Fast);
  TaskPlanningOptions options;
  options.synergies = &synergies;
  options.parameters.seed = 1;
  const TaskPlanningResult result = planTask(task, checking, options);
  std::printf("%s: %s, %zu path nodes, %zu roadmap nodes, %.3f s\n", task.name.c_str(),
              plannerStatusName(result.status).c_str(), result.path.size(), result.statistics.roadmapNodes,
              result.statistics.planningTime);
  return result.statistics.solved() ? 0 : 1;
}
