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

/// The most points a sampled trajectory may hold: 100 s at 1 kHz. Writing them (JSON and CSV, 19
/// joints) takes about 3 s and 350 MB; 10⁶ took ten times that.
inline constexpr double kMaxTrajectorySamples = 1e5;
/// The sampling intervals accepted (s): 0.1 ms (half the phase integration's step) to 1 s.
inline constexpr double kSmallestSampleInterval = 1e-4;
inline constexpr double kLargestSampleInterval = 1.0;

/// Throws InputError (field "sample-interval") for an interval out of range or one that would
/// sample `duration` seconds into more than kMaxTrajectorySamples points.
void checkSampling(double duration, double interval);

/// States at 0, interval, 2·interval, … and at the duration (the last point, at rest).
/// Throws InputError as checkSampling does.
JointTrajectory sampleTrajectory(const TimedPath& timed, std::vector<std::string> jointNames, double interval);

}  // namespace pmdplan
