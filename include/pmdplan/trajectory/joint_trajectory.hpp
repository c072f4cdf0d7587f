#pragma once
// A timed path sampled at a fixed interval, shaped like ROS's trajectory_msgs/JointTrajectory:
// joint names and points with positions, velocities, accelerations and time_from_start.
#include <string>
#include <vector>

#include "pmdplan/trajectory/timed_path.hpp"

namespace pmdplan {

struct JointTrajectory {
  std::vector<std::string> jointNames;
  std::vector<TimedState> points;
};

/// States at 0, interval, 2·interval, … and at the duration (the last point, at rest).
/// Throws std::invalid_argument for an interval that is not positive.
JointTrajectory sampleTrajectory(const TimedPath& timed, std::vector<std::string> jointNames, double interval);

}  // namespace pmdplan
