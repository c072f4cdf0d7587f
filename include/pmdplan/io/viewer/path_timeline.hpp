#pragma once
// The states a path animation steps through: every waypoint, and between two waypoints evenly
// spaced states on the straight joint-space segment (the segment the planner checked), so the
// animation moves at an even pace in the planner's metric however far apart the waypoints are.
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

struct PathTimelineSettings {
  /// Largest distance between consecutive states, in normalised joint units (each joint scaled to
  /// [0, 1] by its limits; Euclidean over all active joints). 0.01 gives about 100 states per unit
  /// of path length: a smooth animation at a size a browser replays without effort.
  double stateSpacing = 0.01;
};

struct PathTimeline {
  std::vector<Configuration> states;
  /// For each waypoint, the index of its state (the first is 0, the last states.size() - 1).
  std::vector<int> waypointStates;
};

/// Throws std::invalid_argument for fewer than one waypoint, a waypoint of the wrong size or a
/// spacing that is not positive.
PathTimeline pathTimeline(const std::vector<Configuration>& waypoints, const RobotModel& robot,
                          const PathTimelineSettings& parameters = {});

}  // namespace pmdplan
