#pragma once
// One planner run on a task: the state and motion checks of the chosen checker, the hand sampler
// of the chosen mode and the PMD roadmap planner, wired the same way for the CLI and the
// benchmarks.
#include <vector>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/pmd_roadmap_planner.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

struct TaskPlanningOptions {
  HandSamplingMode mode = HandSamplingMode::Synergy;
  PlannerParameters parameters = PlannerParameters::defaultsFor(HandSamplingMode::Synergy);
  const SynergyModel* synergies = nullptr;  ///< required for the Synergy mode
};

struct TaskPlanningResult {
  PlannerStatus status = PlannerStatus::NotRun;
  std::vector<Configuration> path;
  PlanningStatistics statistics;
};

/// `checking` must have been built for `task`; its tolerance is the motion checks' resolution.
/// Throws InputError for a model that does not fit the robot's hand (field as the sampler names
/// it, no file) and for bad parameters.
TaskPlanningResult planTask(const Task& task, CollisionChecking& checking, const TaskPlanningOptions& options,
                            ProgressCallback progress = {});

}  // namespace pmdplan
