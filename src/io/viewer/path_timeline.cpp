#include "pmdplan/io/viewer/path_timeline.hpp"

#include <cmath>
#include <stdexcept>

namespace pmdplan {
namespace {

/// Distance in normalised joint units; a joint without a range (lower == upper) counts in its own units.
double normalisedDistance(const Configuration& a, const Configuration& b, const JointLimits& limits) {
  double sum = 0.0;
  for (Eigen::Index j = 0; j < a.size(); ++j) {
    const double range = limits[static_cast<std::size_t>(j)].range();
    const double step = (b[j] - a[j]) / (range > 0.0 ? range : 1.0);
    sum += step * step;
  }
  return std::sqrt(sum);
}

}  // namespace

PathTimeline pathTimeline(const std::vector<Configuration>& waypoints, const RobotModel& robot,
                          const PathTimelineSettings& parameters) {
  if (waypoints.empty()) throw std::invalid_argument("pathTimeline: no waypoints");
  if (!(parameters.stateSpacing > 0.0)) throw std::invalid_argument("pathTimeline: the state spacing must be positive");
  for (const Configuration& q : waypoints)
    if (q.size() != robot.dof())
      throw std::invalid_argument("pathTimeline: a waypoint's size differs from the robot's joint count");

  PathTimeline timeline;
  timeline.waypointStates.push_back(0);
  timeline.states.push_back(waypoints.front());
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    const Configuration& from = waypoints[i - 1];
    const Configuration& to = waypoints[i];
    const double length = normalisedDistance(from, to, robot.activeJoints());
    const int steps = std::max(1, static_cast<int>(std::ceil(length / parameters.stateSpacing)));
    // Interpolated from the segment's ends (not accumulated), so the waypoint itself comes out exact.
    for (int k = 1; k < steps; ++k) timeline.states.push_back(from + (to - from) * (static_cast<double>(k) / steps));
    timeline.states.push_back(to);
    timeline.waypointStates.push_back(static_cast<int>(timeline.states.size()) - 1);
  }
  return timeline;
}

}  // namespace pmdplan
