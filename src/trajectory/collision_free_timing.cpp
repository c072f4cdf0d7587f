#include "pmdplan/trajectory/collision_free_timing.hpp"

namespace pmdplan {

CollisionFreeTiming timeCollisionFree(const std::vector<Configuration>& waypoints,
                                      const std::vector<JointMotionLimit>& limits, const TimingSettings& settings,
                                      StateValidator& states, const SweptDistanceBound& bound, double tolerance,
                                      int halvings) {
  CollisionFreeTiming result;
  TimingSettings attempt = settings;
  for (int k = 0;; ++k) {
    if (k > halvings || attempt.blendTolerance < TimingBounds::kSmallestBlendTolerance) attempt.blendTolerance = 0.0;
    auto timed = std::make_unique<TimedPath>(waypoints, limits, attempt);
    ++result.attempts;
    // A blend the phase integration did not resolve: the path stops at every waypoint instead
    // (tolerance 0, straight segments only, which always keep the limits).
    if (attempt.blendTolerance > 0.0 && !keepsLimits(*timed, limits, attempt)) {
      ++result.limitFailures;
      attempt.blendTolerance = 0.0;
      k = halvings;
      continue;
    }
    const TimedPathInspection inspection = inspectTimedPath(*timed, states, bound, tolerance, true);
    result.statesChecked += inspection.statesChecked;
    if (inspection.free || attempt.blendTolerance == 0.0) {
      result.timed = std::move(timed);
      result.blendTolerance = attempt.blendTolerance;
      return result;
    }
    attempt.blendTolerance /= 2.0;
  }
}

}  // namespace pmdplan
