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
#include <functional>
#include <stdexcept>
#include <utility>

#include "ompl_checker_adapters.hpp"
#include "ompl_pmd_state_sampler.hpp"
#include "pmdplan/bench/ompl_task_space.hpp"
#include "pmdplan/core/stop_request.hpp"
#include "pmdplan/planning/hand_sampling_mode.hpp"

namespace pmdplan {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

using PlannerFactory = std::function<ob::PlannerPtr(const ob::SpaceInformationPtr&)>;

template <typename Planner>
PlannerFactory make() {
  return [](const ob::SpaceInformationPtr& si) -> ob::PlannerPtr { return std::make_shared<Planner>(si); };
}

const std::vector<std::pair<std::string, PlannerFactory>>& plannerFactories() {
  static const std::vector<std::pair<std::string, PlannerFactory>> factories = {
      {"RRTConnect", make<og::RRTConnect>()},
      {"PRM", make<og::PRM>()},
      {"LazyPRM", make<og::LazyPRM>()},
      {"KPIECE1", make<og::KPIECE1>()},
      {"BKPIECE1", make<og::BKPIECE1>()},
      {"EST", make<og::EST>()},
      {"RRT", make<og::RRT>()},
  };
  return factories;
}

const PlannerFactory* findFactory(const std::string& name) {
  for (const auto& [known, factory] : plannerFactories())
    if (known == name) return &factory;
  return nullptr;
}

}  // namespace

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
  if (pmdSampling) {
    std::shared_ptr<const HandSampler> hands =
        makeHandSampler(HandSamplingMode::Synergy, space, pmdSampling->synergies, pmdSampling->parameters.pmdBox);
    installPmdStateSampler(*si->getStateSpace(), space, hands, start, goal, pmdSampling->parameters);
  }

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
  const ob::PlannerStatus status = planner->solve(ob::plannerOrTerminationCondition(
      ob::timedPlannerTerminationCondition(timeLimitSeconds),
      ob::PlannerTerminationCondition([] { return stopRequested(); })));  // core/stop_request.hpp
  result.planningTimeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  result.status = status.asString();
  result.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
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
