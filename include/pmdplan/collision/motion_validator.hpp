#pragma once
// Is the straight joint-space segment between two valid configurations free? (OMPL's
// MotionValidator.) The endpoints are assumed already checked.
#include <cstddef>

#include "pmdplan/model/configuration.hpp"

namespace pmdplan {

class MotionValidator {
 public:
  virtual ~MotionValidator() = default;
  virtual bool isValid(const Configuration& from, const Configuration& to) = 0;
  /// States checked by all isValid calls so far.
  virtual std::size_t statesChecked() const = 0;
};

}  // namespace pmdplan
