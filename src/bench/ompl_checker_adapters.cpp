#include "ompl_checker_adapters.hpp"

#include <algorithm>
#include <cmath>

namespace pmdplan {

Configuration configurationOfState(const PlanningSpace& space, const ompl::base::State* state) {
  const auto* values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
  Eigen::VectorXd unit(space.dof());
  for (int i = 0; i < space.dof(); ++i) unit[i] = values[i];
  return space.denormalise(unit);
}

void setStateFromConfiguration(const PlanningSpace& space, const Configuration& q, ompl::base::State* state) {
  auto* values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
  const Eigen::VectorXd unit = space.normalise(q);
  for (int i = 0; i < space.dof(); ++i) values[i] = unit[i];
}

OmplStateChecker::OmplStateChecker(const ompl::base::SpaceInformationPtr& si, const PlanningSpace& space,
                                   StateValidator& states)
    : ompl::base::StateValidityChecker(si), space_(space), states_(states) {}

bool OmplStateChecker::isValid(const ompl::base::State* state) const {
  return isValid(configurationOfState(space_, state));
}

bool OmplStateChecker::isValid(const Configuration& q) const {
  ++checks_;
  return space_.withinLimits(q) && states_.isValid(q);
}

OmplMotionChecker::OmplMotionChecker(const ompl::base::SpaceInformationPtr& si, const PlanningSpace& space,
                                     const OmplStateChecker& stateChecker, pmdplan::MotionValidator& motions)
    : ompl::base::MotionValidator(si), space_(space), stateChecker_(stateChecker), motions_(motions) {}

bool OmplMotionChecker::checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const {
  const Configuration to = configurationOfState(space_, s2);
  const bool valid = stateChecker_.isValid(to) && motions_.isValid(configurationOfState(space_, s1), to);
  ++(valid ? valid_ : invalid_);
  return valid;
}

bool OmplMotionChecker::checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                                    std::pair<ompl::base::State*, double>& lastValid) const {
  const Configuration from = configurationOfState(space_, s1);
  const Configuration to = configurationOfState(space_, s2);
  const auto pieces = static_cast<int>(std::max(1.0, std::ceil(space_.distance(from, to) / kPieceLength)));
  Configuration pieceStart = from;
  for (int i = 1; i <= pieces; ++i) {
    const double t = static_cast<double>(i) / pieces;
    const Configuration pieceEnd = i == pieces ? to : Configuration(from + t * (to - from));
    if (!stateChecker_.isValid(pieceEnd) || !motions_.isValid(pieceStart, pieceEnd)) {
      const double validFraction = static_cast<double>(i - 1) / pieces;
      if (lastValid.first) setStateFromConfiguration(space_, pieceStart, lastValid.first);
      lastValid.second = validFraction;
      ++invalid_;
      return false;
    }
    pieceStart = pieceEnd;
  }
  ++valid_;
  return true;
}

}  // namespace pmdplan
