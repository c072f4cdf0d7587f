#include "pmdplan/bench/ompl_planning.hpp"

#include <ompl/base/PlannerData.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <utility>

#include "ompl_checker_adapters.hpp"
#include "ompl_pmd_state_sampler.hpp"
#include "pmdplan/bench/ompl_task_space.hpp"
#include "pmdplan/core/stop_request.hpp"

namespace pmdplan {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

using PlannerFactory = std::function<ob::PlannerPtr(const ob::SpaceInformationPtr&)>;

template <typename Planner>
PlannerFactory make() {
  return [](const ob::SpaceInformationPtr& si) -> ob::PlannerPtr { return std::make_shared<Planner>(si); };
}

struct KnownPlanner {
  OmplPlannerKind kind;
  PlannerFactory factory;
};

/// OMPL's planners we run, one line each.
const std::vector<KnownPlanner>& knownPlanners() {
  static const std::vector<KnownPlanner> planners = {
      {{"RRTConnect", "OMPL bidirectional RRT"}, make<og::RRTConnect>()},
      {{"PRM", "OMPL probabilistic roadmap", false}, make<og::PRM>()},  // grows its roadmap in a thread
      {{"LazyPRM", "OMPL PRM with lazy edge checks"}, make<og::LazyPRM>()},
      {{"KPIECE1", "OMPL KPIECE"}, make<og::KPIECE1>()},
      {{"BKPIECE1", "OMPL bidirectional KPIECE"}, make<og::BKPIECE1>()},
      {{"EST", "OMPL expansive space trees"}, make<og::EST>()},
      {{"RRT", "OMPL RRT"}, make<og::RRT>()},
  };
  return planners;
}

const PlannerFactory* findFactory(const std::string& name) {
  for (const KnownPlanner& known : knownPlanners())
    if (known.kind.name == name) return &known.factory;
  return nullptr;
}

}  // namespace

std::vector<OmplPlannerKind> omplPlannerKinds() {
  std::vector<OmplPlannerKind> kinds;
  for (const KnownPlanner& known : knownPlanners()) kinds.push_back(known.kind);
  return kinds;
}

bool isOmplPlannerName(const std::string& name) { return findFactory(name) != nullptr; }

OmplPlanningResult planWithOmpl(const std::string& plannerName, const PlanningSpace& space, StateValidator& states,
                                MotionValidator& motions, const Configuration& start, const Configuration& goal,
                                double timeLimitSeconds, std::uint64_t seed, const OmplPmdSampling* pmdSampling) {
  const PlannerFactory* factory = findFactory(plannerName);
  if (!factory) throw std::invalid_argument("planWithOmpl: unknown OMPL planner '" + plannerName + "'");
  if (seed == 0) throw std::invalid_argument("planWithOmpl: OMPL ignores seed 0");
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed));

  const OmplTaskSpace taskSpace = makeOmplTaskSpace(space, states, motions);
  const ob::SpaceInformationPtr& si = taskSpace.spaceInformation;
  if (pmdSampling)
    installPmdStateSampler(*si->getStateSpace(), space, pmdSampling->hands, start, goal, pmdSampling->parameters);

  ob::ScopedState<> startState(si), goalState(si);
  setStateFromConfiguration(space, start, startState.get());
  setStateFromConfiguration(space, goal, goalState.get());
  const auto problem = std::make_shared<ob::ProblemDefinition>(si);
  problem->setStartAndGoalStates(startState, goalState);

  OmplPlanningResult result;
  const std::size_t motionChecksBefore = motions.statesChecked();
  const auto began = std::chrono::steady_clock::now();
  const ob::PlannerPtr planner = (*factory)(si);
  planner->setProblemDefinition(problem);
  planner->setup();
  const ob::PlannerTerminationCondition stopped([] { return stopRequested(); });  // core/stop_request.hpp
  const ob::PlannerStatus status = planner->solve(
      std::isfinite(timeLimitSeconds)
          ? ob::plannerOrTerminationCondition(ob::timedPlannerTerminationCondition(timeLimitSeconds), stopped)
          : stopped);
  result.planningTimeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  result.status = status.asString();
  result.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
  result.plannerStatus = result.solved                                ? PlannerStatus::Solved
                         : status == ob::PlannerStatus::INVALID_START ? PlannerStatus::InvalidStart
                         : status == ob::PlannerStatus::INVALID_GOAL  ? PlannerStatus::InvalidGoal
                                                                      : PlannerStatus::TimeLimit;
  result.stateChecks = taskSpace.stateChecks();
  result.motionChecks = motions.statesChecked() - motionChecksBefore;
  ob::PlannerData data(si);
  planner->getPlannerData(data);
  result.graphStates = data.numVertices();
  if (result.solved) {
    const auto& states = problem->getSolutionPath()->as<og::PathGeometric>()->getStates();
    for (const ob::State* state : states) result.path.push_back(configurationOfState(space, state));
    // The ends are the normalised start and goal mapped back: equal up to rounding, so restore them.
    if (!result.path.empty()) {
      if (space.distance(result.path.front(), start) < 1e-9) result.path.front() = start;
      if (space.distance(result.path.back(), goal) < 1e-9) result.path.back() = goal;
    }
  }
  return result;
}

}  // namespace pmdplan
