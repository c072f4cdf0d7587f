#pragma once
// Plan a task with any planner: the one service the CLI (`plan`), the benchmarks (`bench`) and
// Python (`pmdplan.plan`) share. The planner comes from a registry (planner_registry.hpp: ours; with
// OMPL's, bench/planner_roster.hpp) and plans on the state and motion checks of the task's
// CollisionChecking. A goal that grasps the task's target is planned in two phases
// (grasp_approach.hpp): the planner's path to the pre-grasp (the approach), then the closing
// segment to the goal. taskApproach and appendClosing are the two phases' wiring on their own.
#include <optional>
#include <vector>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/planning/grasp_approach.hpp"
#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/planner_registry.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

struct TaskPlanningSettings {
  /// The planner that plans the approach, an entry of a registry (ourPlanners() or, with OMPL's,
  /// bench's plannerRoster()), which must outlive the call; nullptr: ours `pmd`.
  const PlannerEntry* planner = nullptr;
  /// Its settings; start from PlannerSettings::defaultsFor(planner->mode).
  PlannerSettings parameters = PlannerSettings::defaultsFor(HandSamplingMode::Synergy);
  const SynergyModel* synergies = nullptr;  ///< required by planners that sample PMDs (usesSynergies)
  GraspSettings grasp;                      ///< how a pre-grasp is derived for a grasp goal
};

struct TaskPlanningResult {
  PlannerStatus status = PlannerStatus::NotRun;
  std::vector<Configuration> path;
  PlanningStatistics statistics;
  std::optional<GraspApproach> grasp;      ///< set when the goal grasps the target
  std::optional<std::size_t> closingFrom;  ///< the pre-grasp's index in `path` (closing phase from there)
};

/// Where a task's approach ends: the pre-grasp of a grasp goal (found as graspApproach finds it, at
/// the checks' tolerance) or the goal itself.
struct TaskApproach {
  std::optional<GraspApproach> grasp;
  /// The pre-grasp search's wall time, which counts in the planning time (0 without a grasp).
  double seconds = 0.0;

  const Configuration& end(const Task& task) const { return grasp ? grasp->pregrasp : task.goal; }
};

/// Throws InputError as graspApproach does.
TaskApproach taskApproach(const Task& task, CollisionChecking& checking, const GraspSettings& settings);

/// Ends a solved approach path (start to approach.end()) with the closing: appends the goal and
/// returns the pre-grasp's index, where the closing phase starts; without a grasp, nullopt and
/// the path unchanged.
std::optional<std::size_t> appendClosing(const Task& task, const TaskApproach& approach,
                                         std::vector<Configuration>& path);

/// One run of the chosen planner on the task. `checking` must have been built for `task`; its
/// tolerance is the motion checks' resolution. `progress` reaches the planner (only the paper
/// planner reports). Throws InputError for a model that does not fit the robot's hand (field as the
/// sampler names it, no file), for bad parameters, and (naming the task file) for a goal that
/// touches anything but the target with the hand or whose pre-grasp cannot be found.
TaskPlanningResult planTask(const Task& task, CollisionChecking& checking, const TaskPlanningSettings& options,
                            ProgressCallback progress = {});

}  // namespace pmdplan
