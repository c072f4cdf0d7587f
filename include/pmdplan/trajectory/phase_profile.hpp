#pragma once
// The time-optimal speed profile of a blended path (Kunz & Stilman, "Time-optimal trajectory
// generation for path following with bounded acceleration and velocity", RSS 2012): integrate
// forward at the largest s̈ from rest; where the trajectory would cross a limit curve, follow the
// velocity limit curve while that is feasible, or else find the next switching point on a limit
// curve, integrate backward from it at the smallest s̈ until it meets the forward trajectory, and go
// on forward from the switching point; finally integrate backward from rest at the end.
//
// The profile is a list of phase points (s, ṡ²) with s increasing; between two, s̈ is constant
// (ṡ² is linear in s), which makes splicing a backward curve onto the forward one exact.
#include <vector>

#include "pmdplan/trajectory/phase_plane.hpp"

namespace pmdplan {

struct PhasePoint {
  double s = 0.0;
  double speedSquared = 0.0;  ///< ṡ²
  double time = 0.0;          ///< from the start of the path
};

struct PhaseProfileSettings {
  /// Integration time step (s).
  double timeStep = 0.0002;
  /// Integration steps (forward and backward together) after which the integration gives up with
  /// std::runtime_error: a backstop, since TimedPath bounds the work before it starts
  /// (TimingBounds::kMaxIntegrationSteps, estimated from the rest-to-rest duration).
  long maxSteps = 20'000'000;
};

/// From rest at s = 0 to rest at s = length. Throws std::runtime_error if the integration fails
/// (a backward curve that never meets the forward one: a bug, not bad input).
std::vector<PhasePoint> timeOptimalProfile(const PhasePlane& plane, const PhaseProfileSettings& settings = {});

}  // namespace pmdplan
