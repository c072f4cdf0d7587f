#include "pmdplan/bench/task_bench.hpp"

#include "pmdplan/core/input_error.hpp"
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
  for (const auto& [label, q] : {std::pair{"start", &task_->start}, std::pair{"goal", &task_->goal}}) {
    const CollisionReport report = validationChecker_->check(*q);
    if (!report.free()) {
      std::string pairs;
      for (const auto& [a, b] : report.pairs) pairs += (pairs.empty() ? "" : ", ") + a + " - " + b;
      throw InputError(task_->file.string(), label,
                       std::string("the ") + label + " configuration is in collision: " + pairs);
    }
  }
}

}  // namespace pmdplan
