#pragma once
// One planner run on a task: the state and motion checks of the chosen checker, the hand sampler
// of the chosen mode and the PMD roadmap planner, wired the same way for the CLI and the
// benchmarks. A goal that grasps the task's target is planned in two phases (grasp_approach.hpp):
// the roadmap planner's path to the pre-grasp (the approach), then the closing segment to the goal.
// The lazy and the bidirectional planners are wired the same way; the progress callback is the paper planner's only.
// taskApproach and appendClosing are the two phases' wiring on their own, for planners of other
// families (OMPL's, src/bench/) to plan a grasp goal exactly as planTask does.
#include <optional>
#include <vector>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/planning/grasp_approach.hpp"
#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/pmd_roadmap_planner.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

/// Which of our planners plans the approach.
enum class RoadmapAlgorithm {
  Paper,    ///< the paper's PMD roadmap (pmd_roadmap_planner.hpp): `pmd`, `full`
  Lazy,     ///< the lazy PMD roadmap (lazy_pmd_planner.hpp): `pmd-lazy`
  Connect,  ///< the bidirectional PMD trees (pmd_connect_planner.hpp): `pmd-connect`
};

struct TaskPlanningSettings {
  RoadmapAlgorithm algorithm = RoadmapAlgorithm::Paper;
  HandSamplingMode mode = HandSamplingMode::Synergy;
  PlannerSettings parameters = PlannerSettings::defaultsFor(HandSamplingMode::Synergy);
  const SynergyModel* synergies = nullptr;  ///< required for the Synergy mode
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

/// `checking` must have been built for `task`; its tolerance is the motion checks' resolution.
/// Throws InputError for a model that does not fit the robot's hand (field as the sampler names
/// it, no file), for bad parameters, and (naming the task file) for a goal that touches anything
/// but the target with the hand or whose pre-grasp cannot be found.
TaskPlanningResult planTask(const Task& task, CollisionChecking& checking, const TaskPlanningSettings& options,
                            ProgressCallback progress = {});

}  // namespace pmdplan
