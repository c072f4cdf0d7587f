#pragma once
// How far can any point of the robot move along a straight joint-space segment? Each joint's lever
// arm bounds how far a point it carries can travel per radian: the distance from the joint origin to
// the farthest point of any geometry it moves, over all configurations (a chain of joint offsets
// plus the shape's enclosing radius). Summed over joints (mimic joints charged to their source),
// this bounds the displacement of every point, so checking states no farther apart than a tolerance
// makes "free" hold up to that tolerance.
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

/// The motion tolerance a check may use, millimetres: below 0.01 mm a segment needs millions of
/// states (and the checkers' numerical margins are of that order); above 100 mm "free" says little.
inline constexpr double kMinToleranceMm = 0.01;
inline constexpr double kMaxToleranceMm = 100.0;
/// The most intervals one segment may need (10^7); more is an InputError naming the tolerance.
inline constexpr long kMaxSegmentIntervals = 10'000'000;

/// Throws InputError (field --tolerance-mm) unless kMinToleranceMm <= mm <= kMaxToleranceMm.
void checkMotionToleranceMm(double mm);

class SweptDistanceBound {
 public:
  explicit SweptDistanceBound(const RobotModel& model);

  /// Metres moved per unit of each active joint (radian or metre), mimic joints included.
  const std::vector<double>& leverArms() const { return leverArms_; }
  /// Upper bound on how far any point of the robot moves from `from` to `to`.
  double bound(const Configuration& from, const Configuration& to) const;
  /// Number of equal intervals the segment needs so that no point moves more than `tolerance`
  /// between consecutive states (at least 1); more than kMaxSegmentIntervals is an InputError.
  long intervals(const Configuration& from, const Configuration& to, double tolerance) const;

 private:
  std::vector<double> leverArms_;
};

}  // namespace pmdplan
