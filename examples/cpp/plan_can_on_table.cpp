// Plans the built-in task can_on_table with the paper's planner through the installed library:
// load the task and the robot's shipped synergy model, build the fast collision checks, plan;
// then the same planner once more as an OMPL planner (OmplPmdPlanner) through OMPL's SimpleSetup.
#include <ompl/base/ScopedState.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>

#include <cstdio>
#include <memory>

#include "pmdplan/bench/ompl_pmd_planner.hpp"
#include "pmdplan/bench/ompl_task_space.hpp"
#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/planning/robot_planning_space.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/world/task.hpp"

int main() {
  using namespace pmdplan;
  const Task task = loadTaskByName("can_on_table");
  const auto synergies =
      std::make_shared<const SynergyModel>(loadSynergyModel(defaultSynergyModelPath(task.robot->name())));
  CollisionChecking checking(task, CheckerKind::Fast);
  TaskPlanningSettings options;
  options.synergies = synergies.get();
  options.parameters.seed = 1;
  const TaskPlanningResult result = planTask(task, checking, options);
  std::printf("%s: %s, %zu path nodes, %zu roadmap nodes, %.3f s\n", task.name.c_str(),
              plannerStatusName(result.status).c_str(), result.path.size(), result.statistics.roadmapNodes,
              result.statistics.planningTime);

  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  const PlanningSpace space = planningSpaceFromRobot(*task.robot);
  const OmplTaskSpace omplSpace = makeOmplTaskSpace(space, checking.states(), checking.motions());
  ompl::geometric::SimpleSetup setup(omplSpace.spaceInformation);
  ompl::base::ScopedState<> start(omplSpace.spaceInformation), goal(omplSpace.spaceInformation);
  setOmplState(space, task.start, start.get());
  setOmplState(space, task.goal, goal.get());
  setup.setStartAndGoalStates(start, goal);
  setup.setPlanner(
      std::make_shared<OmplPmdPlanner>(omplSpace.spaceInformation, space, HandSamplingMode::Synergy, synergies));
  const bool omplSolved = setup.solve(30.0) == ompl::base::PlannerStatus::EXACT_SOLUTION;
  std::printf("OMPL %s: %s, %zu path states\n", setup.getPlanner()->getName().c_str(),
              omplSolved ? "solved" : "not solved", omplSolved ? setup.getSolutionPath().getStateCount() : 0u);
  return result.statistics.solved() && omplSolved ? 0 : 1;
}
