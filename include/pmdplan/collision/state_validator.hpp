#pragma once
// Is this configuration collision-free? The planner's only view of geometry (like OMPL's
// StateValidityChecker). Implementations count their checks for the statistics.
#include <cstddef>

#include "pmdplan/model/configuration.hpp"

namespace pmdplan {

class StateValidator {
 public:
  virtual ~StateValidator() = default;
  /// Free of self-collision (enabled pairs) and of collision with the environment.
  virtual bool isValid(const Configuration& q) = 0;
  /// Arm links only: free of self-collision among themselves (Algorithm 1's SELFCOLLISION(c^a)).
  virtual bool isArmValid(const Configuration& q) = 0;
  /// Number of isValid / isArmValid calls so far.
  virtual std::size_t checkCount() const = 0;
};

}  // namespace pmdplan
