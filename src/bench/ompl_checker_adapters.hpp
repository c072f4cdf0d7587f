#pragma once
// Our StateValidator and MotionValidator behind OMPL's interfaces, for states of a
// RealVectorStateSpace over the normalised joint box.
#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/planning/planning_space.hpp"

namespace pmdplan {

Configuration configurationOfState(const PlanningSpace& space, const ompl::base::State* state);
void setStateFromConfiguration(const PlanningSpace& space, const Configuration& q, ompl::base::State* state);

/// Counts the states it is asked about (OMPL's planners check each drawn state once).
class OmplStateChecker final : public ompl::base::StateValidityChecker {
 public:
  OmplStateChecker(const ompl::base::SpaceInformationPtr& si, const PlanningSpace& space, StateValidator& states);
  using ompl::base::StateValidityChecker::isValid;  // OMPL's forms with a clearance stay callable
  bool isValid(const ompl::base::State* state) const override;
  bool isValid(const Configuration& q) const;
  std::size_t checks() const { return checks_; }

 private:
  const PlanningSpace& space_;
  StateValidator& states_;
  mutable std::size_t checks_ = 0;
};

/// OMPL expects checkMotion to check the end state too (RRTConnect extends to unchecked states),
/// while our MotionValidator takes both ends as checked: the end is checked here first.
class OmplMotionChecker final : public ompl::base::MotionValidator {
 public:
  /// `stateChecker` checks (and counts) the end states.
  OmplMotionChecker(const ompl::base::SpaceInformationPtr& si, const PlanningSpace& space,
                    const OmplStateChecker& stateChecker, pmdplan::MotionValidator& motions);
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  /// KPIECE's form: on a collision, the last valid state along the motion and its fraction. Our
  /// checker only answers yes or no, so the motion is walked in pieces of at most `kPieceLength`
  /// (normalised units), each piece's end checked as a state and the piece as a motion; the last
  /// valid state is the start of the first piece that fails.
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& lastValid) const override;

  static constexpr double kPieceLength = 0.05;

 private:
  const PlanningSpace& space_;
  const OmplStateChecker& stateChecker_;
  pmdplan::MotionValidator& motions_;
};

}  // namespace pmdplan
