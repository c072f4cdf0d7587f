#pragma once
// Is a timed path still collision-free where its blends leave the checked segments? Every segment
// of the blended paths is checked at states so close that no point of the robot moves more than
// `tolerance` between two of them — the segment checker's guarantee, carried over to arcs: along a
// segment joint i moves at most max|dq_i/ds| per unit of path length (|x_i| on a line,
// sqrt(x_i² + y_i²) on an arc), so the lever-arm bound Σ lever_i · max|dq_i/ds| · Δs bounds how
// far any point moves over Δs.
#include <optional>

#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/trajectory/timed_path.hpp"

namespace pmdplan {

struct TimedPathInspection {
  bool free = true;
  long statesChecked = 0;
  /// The first colliding state's configuration, when not free.
  std::optional<Configuration> firstCollision;
};

/// `arcsOnly` skips the straight pieces: they lie on the original segments, which the planner
/// and `validate` have already checked at the same tolerance.
TimedPathInspection inspectTimedPath(const TimedPath& timed, StateValidator& states, const SweptDistanceBound& bound,
                                     double tolerance, bool arcsOnly = false);

}  // namespace pmdplan
