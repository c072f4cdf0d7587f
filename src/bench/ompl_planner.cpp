#include "pmdplan/bench/ompl_planner.hpp"

#include <chrono>
#include <stdexcept>
#include <utility>

#include "pmdplan/bench/ompl_planning.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/path_smoothing.hpp"
#include "pmdplan/planning/planner_run.hpp"

namespace pmdplan {

OmplPlanner::OmplPlanner(const PlannerContext& context, std::string omplName, bool pmdSampling)
    : space_(context.space),
      states_(context.states),
      motions_(context.motions),
      settings_(context.settings),
      omplName_(std::move(omplName)) {
  if (!isOmplPlannerName(omplName_))
    throw std::invalid_argument("OmplPlanner: unknown OMPL planner '" + omplName_ + "'");
  if (pmdSampling) pmdHands_ = makeHandSampler(HandSamplingMode::Synergy, space_, context.synergies, settings_.pmdBox);
}

std::string OmplPlanner::name() const { return "ompl:" + omplName_ + (pmdHands_ ? "@pmd" : ""); }

void OmplPlanner::setStartAndGoal(Configuration start, Configuration goal) {
  start_ = std::move(start);
  goal_ = std::move(goal);
}

void OmplPlanner::setup() {
  settings_.check();
  if (settings_.seed == 0) throw InputError("", "seed", "OMPL ignores seed 0; expected a positive seed");
  space_.check();
  checkStartAndGoal(space_, start_, goal_, "OmplPlanner");
}

void OmplPlanner::clear() {
  path_.clear();
  statistics_ = {};
}

PlannerStatus OmplPlanner::solve() {
  setup();
  clear();
  // Not all of OMPL's planners check the goal; these two checks are not OMPL's work, so they are
  // counted only when they end the run.
  statistics_.stateChecks = 1;
  if (!states_.isValid(start_)) return finish(PlannerStatus::InvalidStart);
  statistics_.stateChecks = 2;
  if (!states_.isValid(goal_)) return finish(PlannerStatus::InvalidGoal);

  const OmplPmdSampling pmdSampling{pmdHands_, settings_};
  const OmplPlanningResult run = planWithOmpl(omplName_, space_, states_, motions_, start_, goal_, settings_.timeLimit,
                                              settings_.seed, pmdHands_ ? &pmdSampling : nullptr);
  statistics_.planningTime = run.planningTimeSeconds;
  statistics_.samples = statistics_.stateChecks = run.stateChecks;
  statistics_.motionChecks = run.motionChecks;
  statistics_.roadmapNodes = run.graphStates;
  if (!run.solved) return finish(run.plannerStatus);

  statistics_.pathNodesBeforeSmoothing = run.path.size();
  statistics_.pathLengthBeforeSmoothing = pathLength(run.path, space_);
  if (settings_.smooth) {
    const std::size_t motionChecksBefore = motions_.statesChecked();
    const auto began = std::chrono::steady_clock::now();
    path_ = smoothPath(run.path, space_, motions_);
    statistics_.smoothingTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    statistics_.motionChecks += motions_.statesChecked() - motionChecksBefore;
  } else {
    path_ = run.path;
  }
  statistics_.pathNodes = path_.size();
  statistics_.pathLength = pathLength(path_, space_);
  return finish(PlannerStatus::Solved);
}

PlannerStatus OmplPlanner::finish(PlannerStatus status) {
  statistics_.status = status;
  return status;
}

std::vector<PlannerEntry> omplPlannerEntries() {
  std::vector<PlannerEntry> entries;
  for (const bool pmdSampling : {false, true})
    for (const OmplPlannerKind& kind : omplPlannerKinds()) {
      PlannerEntry entry;
      entry.name = "ompl:" + kind.name + (pmdSampling ? "@pmd" : "");
      entry.description = kind.description + (pmdSampling ? ", states from PMD sampling" : "");
      entry.allocate = [name = kind.name, pmdSampling](const PlannerContext& context) -> std::unique_ptr<Planner> {
        return std::make_unique<OmplPlanner>(context, name, pmdSampling);
      };
      entry.mode = HandSamplingMode::Synergy;
      entry.usesSynergies = pmdSampling;
      entry.family = PlannerFamily::Ompl;
      entry.repeatable = kind.repeatable;
      entries.push_back(std::move(entry));
    }
  return entries;
}

}  // namespace pmdplan
