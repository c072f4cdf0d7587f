#pragma once
// What every run on one task shares, built once before the runs: the task, its planning space,
// the planners' checks (CollisionChecking of the chosen kind and tolerance), a separate exact
// checker that validates the returned paths at the same tolerance, and the synergy model the
// PMD planner samples and the human-likeness metrics measure with. Built in the parent process
// and used by the forked run processes, so nothing in it may own threads (a forked child has only
// the thread that forked).
#include <memory>
#include <string>
#include <vector>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/synergy/synergy_model.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

class TaskBench {
 public:
  /// `synergies` is borrowed and must outlive this object; `synergyFile` names it in errors.
  /// Throws InputError if the model's joints are not the robot's, or plan would refuse the task's
  /// start or goal (grasp_rule.hpp: a goal may grasp its target; planning/grasp_approach.hpp).
  TaskBench(Task task, CheckerKind checker, double toleranceMetres, const SynergyModel& synergies,
            const std::string& synergyFile);
  TaskBench(const TaskBench&) = delete;
  TaskBench& operator=(const TaskBench&) = delete;

  const Task& task() const { return *task_; }
  const PlanningSpace& space() const { return space_; }
  CollisionChecking& checking() { return *checking_; }
  ExactCollisionChecker& validationChecker() { return *validationChecker_; }
  const SegmentChecker& validationSegments() const { return *validationSegments_; }
  const SynergyModel& synergies() const { return synergies_; }
  const std::vector<int>& synergySlots() const { return synergySlots_; }

 private:
  std::unique_ptr<Task> task_;  // first: the checkers keep references to it
  PlanningSpace space_;
  std::unique_ptr<CollisionChecking> checking_;
  std::unique_ptr<ExactCollisionChecker> validationChecker_;
  std::unique_ptr<SegmentChecker> validationSegments_;
  const SynergyModel& synergies_;
  std::vector<int> synergySlots_;
};

}  // namespace pmdplan
