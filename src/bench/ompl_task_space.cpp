#include "pmdplan/bench/ompl_task_space.hpp"

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include "ompl_checker_adapters.hpp"

namespace pmdplan {

OmplTaskSpace makeOmplTaskSpace(const PlanningSpace& space, StateValidator& states, MotionValidator& motions) {
  const auto stateSpace = std::make_shared<ompl::base::RealVectorStateSpace>(static_cast<unsigned>(space.dof()));
  stateSpace->setBounds(0.0, 1.0);
  const auto si = std::make_shared<ompl::base::SpaceInformation>(stateSpace);
  const auto stateChecker = std::make_shared<OmplStateChecker>(si, space, states);
  si->setStateValidityChecker(stateChecker);
  si->setMotionValidator(std::make_shared<OmplMotionChecker>(si, space, *stateChecker, motions));
  si->setup();
  return {si, [stateChecker] { return stateChecker->checks(); }};
}

void setOmplState(const PlanningSpace& space, const Configuration& q, ompl::base::State* state) {
  setStateFromConfiguration(space, q, state);
}

Configuration configurationOfOmplState(const PlanningSpace& space, const ompl::base::State* state) {
  return configurationOfState(space, state);
}

}  // namespace pmdplan
