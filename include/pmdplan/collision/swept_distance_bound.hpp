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

class SweptDistanceBound {
public:
  explicit SweptDistanceBound(const RobotModel& model);

  /// Metres moved per unit of each active joint (radian or metre), mimic joints included.
  const std::vector<double>& leverArms() const { return leverArms_; }
  /// Upper bound on how far any point of the robot moves from `from` to `to`.
  double bound(const Configuration& from, const Configuration& to) const;
  /// Number of equal intervals the segment needs so that no point moves more than `tolerance`
  /// between consecutive states (at least 1).
  long intervals(const Configuration& from, const Configuration& to, double tolerance) const;

private:
  std::vector<double> leverArms_;
};

}  // namespace pmdplan
