#pragma once
// Timing a collision-free path so that the timed path stays collision-free: the blends are checked
// (inspectTimedPath, arcs only — the straight pieces lie on the path's own checked segments), and
// while one collides the blending tolerance is halved, down to 0 (stopping at every waypoint:
// exactly the checked segments). A timing that breaks the joints' limits (keepsLimits: the phase
// integration can miss a switching point at a blend) falls back to 0 at once, and a tolerance
// halved below TimingBounds::kSmallestBlendTolerance becomes 0.
#include <memory>

#include "pmdplan/trajectory/timed_path_inspection.hpp"

namespace pmdplan {

struct CollisionFreeTiming {
  std::unique_ptr<TimedPath> timed;
  double blendTolerance = 0.0;  ///< the tolerance that gave a free path
  long statesChecked = 0;       ///< over all attempts
  int attempts = 0;
  int limitFailures = 0;  ///< attempts whose timing broke the joints' limits (keepsLimits)
};

/// Halves the tolerance at most `halvings` times before falling back to 0.
CollisionFreeTiming timeCollisionFree(const std::vector<Configuration>& waypoints,
                                      const std::vector<JointMotionLimit>& limits, const TimingSettings& settings,
                                      StateValidator& states, const SweptDistanceBound& bound, double tolerance,
                                      int halvings = 6);

}  // namespace pmdplan
