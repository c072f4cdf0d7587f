#pragma once
// A path timed optimally under per-joint velocity and acceleration limits (Kunz & Stilman's TOTG):
// the waypoints joined by straight joint-space segments with circular blends at the corners, and
// the fastest speed profile along them that keeps every joint within its limits. Corners that
// reverse the direction (and, with a blending tolerance of 0, every corner) are passed at rest.
#include <memory>
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/trajectory/blended_path.hpp"
#include "pmdplan/trajectory/joint_motion_limits.hpp"
#include "pmdplan/trajectory/phase_profile.hpp"

namespace pmdplan {

/// The ranges TimingSettings::check enforces, and the work a timing may take (docs/trajectories.md).
struct TimingBounds {
  /// Blend tolerances other than 0 (rad): below 10⁻³ the blends' arcs get shorter than the phase
  /// integration resolves (at 10⁻⁴ a few random paths in a hundred exceed their acceleration limits
  /// hundreds of times; at 10⁻⁸ every corner of can_on_table's path does); above 1 rad (ten times
  /// MoveIt's default path tolerance) a blend is bounded by half its segments anyway.
  static constexpr double kSmallestBlendTolerance = 1e-3;
  static constexpr double kLargestBlendTolerance = 1.0;
  /// --velocity-scale / --acceleration-scale: 1 % of the limits at least.
  static constexpr double kSmallestScale = 0.01;
  /// Phase-integration steps one timing may take, estimated before it starts (restToRestDuration /
  /// timeStep): 5·10⁵ steps are 100 s of trajectory at the 0.2 ms step, about 2 s of integration.
  static constexpr double kMaxIntegrationSteps = 5e5;
};

struct TimingSettings {
  /// Largest distance of the blended path from a corner waypoint (Euclidean joint-space norm,
  /// radians); 0 stops at every waypoint, otherwise in [TimingBounds::kSmallestBlendTolerance,
  /// kLargestBlendTolerance]. MoveIt's default path tolerance is 0.1; 0.01 keeps the blends near the
  /// checked segments (a point of the robot within about 1 cm of the checked path on this robot's
  /// lever arms).
  double blendTolerance = 0.01;
  /// Fractions of the velocity and acceleration limits used, in [TimingBounds::kSmallestScale, 1].
  double velocityScale = 1.0;
  double accelerationScale = 1.0;
  /// Phase-plane integration step (s). MoveIt uses 1 ms; 0.2 ms keeps the joints' accelerations
  /// within 0.5 % of their limits (s̈ is chosen at one end of each step).
  double timeStep = 0.0002;
  /// Throws InputError (field = the option's name without dashes) for values out of range.
  void check() const;
};

/// The path's duration at rest at every waypoint (blend tolerance 0: each straight segment at the
/// largest acceleration to its speed limit and back, in closed form). Computed before any
/// integration to bound the work; the blended timing's duration is within a few percent of it.
double restToRestDuration(const std::vector<Configuration>& waypoints, const std::vector<JointMotionLimit>& limits,
                          const TimingSettings& settings);

/// Throws InputError (field "duration") when timing `waypoints` would take more than
/// TimingBounds::kMaxIntegrationSteps integration steps.
void checkTimingWork(const std::vector<Configuration>& waypoints, const std::vector<JointMotionLimit>& limits,
                     const TimingSettings& settings);

struct TimedState {
  double time = 0.0;
  Configuration position;
  Eigen::VectorXd velocity;
  Eigen::VectorXd acceleration;
};

class TimedPath {
 public:
  /// `limits` one per joint of the waypoints. Consecutive equal waypoints are merged; a path with
  /// a single distinct waypoint has duration 0. Throws InputError for settings out of range and for
  /// a timing that would take too long (checkTimingWork), before any integration.
  TimedPath(const std::vector<Configuration>& waypoints, const std::vector<JointMotionLimit>& limits,
            const TimingSettings& settings = {});

  double duration() const;
  /// The state at time t (clamped to [0, duration()]).
  TimedState at(double t) const;
  /// The blended paths, one per stretch between two stops.
  std::vector<const BlendedPath*> paths() const;

 private:
  struct Piece {
    std::unique_ptr<BlendedPath> path;
    std::vector<PhasePoint> profile;
    double startTime = 0.0;
  };
  std::vector<Piece> pieces_;
  Configuration rest_;
};

/// Whether the timed path keeps every joint within `limits` scaled by the settings' scales:
/// resampled every millisecond, no velocity above its limit by more than 10⁻³ and no change of
/// velocity between two samples faster than the acceleration limit allows by more than 1 %.
bool keepsLimits(const TimedPath& timed, const std::vector<JointMotionLimit>& limits, const TimingSettings& settings);

}  // namespace pmdplan
