#include "pmdplan/bench/task_bench.hpp"

#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/planning/grasp_approach.hpp"
#include "pmdplan/planning/robot_planning_space.hpp"
#include "pmdplan/synergy/synergy_readout.hpp"

namespace pmdplan {

TaskBench::TaskBench(Task task, CheckerKind checker, double toleranceMetres, const SynergyModel& synergies,
                     const std::string& synergyFile)
    : task_(std::make_unique<Task>(std::move(task))),
      space_(planningSpaceFromRobot(*task_->robot)),
      checking_(std::make_unique<CollisionChecking>(*task_, checker, toleranceMetres)),
      validationChecker_(std::make_unique<ExactCollisionChecker>(*task_)),
      validationSegments_(std::make_unique<SegmentChecker>(*validationChecker_, *task_->robot, toleranceMetres)),
      synergies_(synergies),
      synergySlots_(modelJointSlots(synergies, *task_->robot, synergyFile)) {
  // The start and goal plan takes, before any run: a grasp goal whose pre-grasp serves too.
  if (const auto refused = GraspRule(*task_).startRefusal(*validationChecker_)) refused->raise(*task_);
  if (const auto refused = examineGoal(*task_, *validationChecker_, toleranceMetres).refusal) refused->raise(*task_);
}

}  // namespace pmdplan
