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

struct TimingSettings {
  /// Largest distance of the blended path from a corner waypoint (Euclidean joint-space norm,
  /// radians); 0 stops at every waypoint. MoveIt's default path tolerance is 0.1; 0.01 keeps the
  /// blends near the checked segments (a point of the robot within about 1 cm of the checked path on
  /// this robot's lever arms).
  double blendTolerance = 0.01;
  /// Fractions of the velocity and acceleration limits used, in (0, 1].
  double velocityScale = 1.0;
  double accelerationScale = 1.0;
  /// Phase-plane integration step (s). MoveIt uses 1 ms; 0.2 ms keeps the joints' accelerations
  /// within 0.5 % of their limits (s̈ is chosen at one end of each step).
  double timeStep = 0.0002;
  /// Throws InputError (field = the option's name without dashes) for values out of range.
  void check() const;
};

struct TimedState {
  double time = 0.0;
  Configuration position;
  Eigen::VectorXd velocity;
  Eigen::VectorXd acceleration;
};

class TimedPath {
 public:
  /// `limits` one per joint of the waypoints. Consecutive equal waypoints are merged; a path with
  /// a single distinct waypoint has duration 0.
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

}  // namespace pmdplan
