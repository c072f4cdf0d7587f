#pragma once
// The arm region of pmd-connect and of the OMPL PMD sampler: every arm box around the start-goal
// segment has a half-size drawn log-uniformly between rho_a and the region's largest half-size,
// which starts at rho_a and grows by a factor (capped at 1, the whole normalised arm box) each
// time the caller says so. Half the boxes stay within the geometric mean of the two: most samples
// remain near the straight line however far the region has grown.
#include <algorithm>
#include <cmath>

namespace pmdplan {

class ArmBoxScales {
 public:
  /// `smallest`: rho_a, in (0, 1]; `growth` >= 1.
  ArmBoxScales(double smallest, double growth) : smallest_(smallest), largest_(smallest), growth_(growth) {}

  /// The half-size for a number `u` in [0, 1): rho_a · (largest / rho_a)^u.
  double halfSize(double u) const { return smallest_ * std::pow(largest_ / smallest_, u); }
  void grow() { largest_ = std::min(largest_ * growth_, 1.0); }
  double largest() const { return largest_; }

 private:
  double smallest_;
  double largest_;
  double growth_;
};

}  // namespace pmdplan
