#pragma once
// An OMPL problem space for one of our planning spaces: a RealVectorStateSpace over the normalised
// joint box [0, 1]^n whose states are checked by our StateValidator and whose motions by our
// MotionValidator (the checks every planner of a comparison shares). OMPL's planners, and ours
// through OmplPmdPlanner, plan in it.
#include <ompl/base/SpaceInformation.h>

#include <functional>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/planning/planning_space.hpp"

namespace pmdplan {

struct OmplTaskSpace {
  ompl::base::SpaceInformationPtr spaceInformation;  ///< set up, checkers installed
  /// States the validity checker has been asked about so far (motion ends included).
  std::function<std::size_t()> stateChecks;
};

/// `space`, `states` and `motions` are borrowed: they must outlive the returned space information.
OmplTaskSpace makeOmplTaskSpace(const PlanningSpace& space, StateValidator& states, MotionValidator& motions);

/// A configuration as a state of that space, and back.
void setOmplState(const PlanningSpace& space, const Configuration& q, ompl::base::State* state);
Configuration configurationOfOmplState(const PlanningSpace& space, const ompl::base::State* state);

}  // namespace pmdplan
