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
  /// The index of the first of `count` configurations whose isValid is `valid` (count if none),
  /// checked in order until it is found: firstWithValidity(qs, n, false) == n says all n are free,
  /// firstWithValidity(qs, n, true) picks the first free one. Checkers that test several
  /// configurations at once (the fast one, FastCollisionChecker::kLanes) override it and may check
  /// a few past the one found.
  virtual int firstWithValidity(const Configuration* const* configurations, int count, bool valid) {
    for (int i = 0; i < count; ++i)
      if (isValid(*configurations[i]) == valid) return i;
    return count;
  }
  /// Number of isValid / isArmValid calls so far (and of configurations firstWithValidity checked).
  virtual std::size_t checkCount() const = 0;
};

}  // namespace pmdplan
