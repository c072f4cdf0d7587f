#include "pmdplan/planning/pmd_planner_base.hpp"

#include <stdexcept>

namespace pmdplan {

PmdPlannerBase::PmdPlannerBase(PlanningSpace space, StateValidator& stateValidator, MotionValidator& motionValidator,
                               std::unique_ptr<HandSampler> handSampler, PlannerSettings parameters, std::string name)
    : space_(std::move(space)),
      stateValidator_(stateValidator),
      motionValidator_(motionValidator),
      handSampler_(std::move(handSampler)),
      parameters_(parameters),
      name_(std::move(name)) {
  if (!handSampler_) throw std::invalid_argument(name_ + ": a hand sampler is required");
}

void PmdPlannerBase::setStartAndGoal(Configuration start, Configuration goal) {
  start_ = std::move(start);
  goal_ = std::move(goal);
  armSampler_.reset();
}

void PmdPlannerBase::setupProblem() {
  parameters_.check();
  space_.check();
  checkStartAndGoal(space_, start_, goal_, name_);
  armSampler_.emplace(space_, start_, goal_);
}

void PmdPlannerBase::clearResults() {
  path_.clear();
  unsmoothedPath_.clear();
  statistics_ = {};
}

void PmdPlannerBase::beginRun(int segmentPointDimension) {
  points_.reset(parameters_.sequence, parameters_.seed,
                {handSampler_->maxDimension(), static_cast<int>(space_.armIndices.size()), segmentPointDimension});
  run_.begin(parameters_.timeLimit, motionValidator_);
}

std::optional<PlannerStatus> PmdPlannerBase::checkStartAndGoalStates() {
  ++statistics_.stateChecks;
  if (!stateValidator_.isValid(start_)) return PlannerStatus::InvalidStart;
  ++statistics_.stateChecks;
  if (!stateValidator_.isValid(goal_)) return PlannerStatus::InvalidGoal;
  return std::nullopt;
}

PlannerStatus PmdPlannerBase::finishRun(PlannerStatus status, std::size_t roadmapNodes, std::size_t roadmapEdges) {
  run_.end(status, motionValidator_, statistics_);
  statistics_.roadmapNodes = roadmapNodes;
  statistics_.roadmapEdges = roadmapEdges;
  return status;
}

}  // namespace pmdplan
