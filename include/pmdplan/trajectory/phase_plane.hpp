#pragma once
// The phase plane (s, ṡ) of a blended path under per-joint velocity and acceleration limits
// (Kunz & Stilman): joint i moves at q'_i ṡ and accelerates at q'_i s̈ + q''_i ṡ², so its limits
// bound ṡ from above (the velocity and acceleration limit curves) and s̈ to an interval at each
// (s, ṡ).
#include <utility>
#include <vector>

#include "pmdplan/trajectory/blended_path.hpp"

namespace pmdplan {

class PhasePlane {
 public:
  /// Limits per joint, in the path's dimension order (all positive).
  PhasePlane(const BlendedPath& path, std::vector<double> velocity, std::vector<double> acceleration);

  const BlendedPath& path() const { return path_; }
  /// Largest ṡ at which some s̈ keeps every joint within its acceleration (infinite on lines).
  double accelerationLimit(double s, bool before = false) const;
  /// Largest ṡ keeping every joint within its velocity limit.
  double velocityLimit(double s, bool before = false) const;
  /// d/ds of velocityLimit (0 on lines).
  double velocityLimitSlope(double s, bool before = false) const;
  double limit(double s, bool before = false) const;
  /// [s̈_min, s̈_max] at (s, ṡ); empty (min > max) above the acceleration limit curve.
  std::pair<double, double> accelerationRange(double s, double speed, bool before = false) const;

 private:
  const BlendedPath& path_;
  std::vector<double> velocity_;
  std::vector<double> acceleration_;
};

}  // namespace pmdplan
