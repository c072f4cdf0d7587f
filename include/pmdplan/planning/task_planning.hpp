#pragma once
// One planner run on a task: the exact checker, the motion checks at a tolerance, the hand
// sampler of the chosen mode and the PMD roadmap planner, wired the same way for the CLI and the
// benchmarks.
#include <vector>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/pmd_roadmap_planner.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

struct TaskPlanningOptions {
  HandSamplingMode mode = HandSamplingMode::Synergy;
  PlannerParameters parameters = PlannerParameters::defaultsFor(HandSamplingMode::Synergy);
  double toleranceMetres = 0.001;     ///< motion checks: no point moves more between two states
  const SynergyModel* synergies = nullptr;  ///< required for the Synergy mode
};

struct TaskPlanningResult {
  PlannerStatus status = PlannerStatus::NotRun;
  std::vector<Configuration> path;
  PlanningStatistics statistics;
};

/// `checker` must have been built for `task`. Throws InputError for a model that does not fit the
/// robot's hand (field as the sampler names it, no file) and for bad parameters.
TaskPlanningResult planTask(const Task& task, ExactCollisionChecker& checker, const TaskPlanningOptions& options,
                            ProgressCallback progress = {});

}  // namespace pmdplan
