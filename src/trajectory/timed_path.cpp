#include "pmdplan/trajectory/timed_path.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

void TimingSettings::check() const {
  using B = TimingBounds;
  if (!(blendTolerance == 0.0 ||
        (blendTolerance >= B::kSmallestBlendTolerance && blendTolerance <= B::kLargestBlendTolerance)))
    throw InputError("", "blend-tolerance", "expected 0 (stop at every waypoint) or radians from 0.001 to 1");
  if (!(velocityScale >= B::kSmallestScale && velocityScale <= 1.0))
    throw InputError("", "velocity-scale", "expected a fraction from 0.01 to 1");
  if (!(accelerationScale >= B::kSmallestScale && accelerationScale <= 1.0))
    throw InputError("", "acceleration-scale", "expected a fraction from 0.01 to 1");
  if (!(timeStep > 0.0 && timeStep <= 0.1)) throw InputError("", "time-step", "expected seconds in (0, 0.1]");
}

double restToRestDuration(const std::vector<Configuration>& waypoints, const std::vector<JointMotionLimit>& limits,
                          const TimingSettings& settings) {
  double duration = 0.0;
  for (std::size_t k = 1; k < waypoints.size(); ++k) {
    const Eigen::VectorXd step = waypoints[k] - waypoints[k - 1];
    const double length = step.norm();
    if (!(length > 0.0)) continue;
    // Along the unit direction x the path speed is bounded by min vᵢ/|xᵢ| and its acceleration by
    // min aᵢ/|xᵢ|: a trapezoid (or a triangle when the segment is too short to reach the speed).
    double speed = std::numeric_limits<double>::infinity(), acceleration = speed;
    for (std::size_t j = 0; j < limits.size(); ++j) {
      const double share = std::abs(step[static_cast<Eigen::Index>(j)]) / length;
      if (share == 0.0) continue;
      speed = std::min(speed, limits[j].velocity * settings.velocityScale / share);
      acceleration = std::min(acceleration, limits[j].acceleration * settings.accelerationScale / share);
    }
    duration += length >= speed * speed / acceleration ? length / speed + speed / acceleration
                                                       : 2.0 * std::sqrt(length / acceleration);
  }
  return duration;
}

void checkTimingWork(const std::vector<Configuration>& waypoints, const std::vector<JointMotionLimit>& limits,
                     const TimingSettings& settings) {
  const double duration = restToRestDuration(waypoints, limits, settings);
  const double longest = TimingBounds::kMaxIntegrationSteps * settings.timeStep;
  if (!(duration <= longest)) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "the path takes about %.4g s at these limits (at rest at every waypoint); expected at most %g s "
                  "(%g integration steps of %g s): raise the velocity and acceleration limits or their scales",
                  duration, longest, TimingBounds::kMaxIntegrationSteps, settings.timeStep);
    throw InputError("", "duration", text);
  }
}

bool keepsLimits(const TimedPath& timed, const std::vector<JointMotionLimit>& limits, const TimingSettings& settings) {
  constexpr double kInterval = 0.001, kVelocitySlack = 1e-3, kAccelerationSlack = 1e-2;
  TimedState previous = timed.at(0.0);
  const auto steps = static_cast<long>(std::ceil(timed.duration() / kInterval));
  for (long k = 1; k <= steps; ++k) {
    const TimedState state = timed.at(static_cast<double>(k) * kInterval);
    const double dt = state.time - previous.time;
    for (std::size_t j = 0; j < limits.size(); ++j) {
      const auto i = static_cast<Eigen::Index>(j);
      const double velocity = limits[j].velocity * settings.velocityScale;
      const double acceleration = limits[j].acceleration * settings.accelerationScale;
      if (!(std::abs(state.velocity[i]) <= velocity * (1.0 + kVelocitySlack))) return false;
      if (dt > 0.0 && !(std::abs(state.velocity[i] - previous.velocity[i]) <=
                        acceleration * (1.0 + kAccelerationSlack) * dt + 1e-12))
        return false;
    }
    previous = state;
  }
  return true;
}

TimedPath::TimedPath(const std::vector<Configuration>& waypoints, const std::vector<JointMotionLimit>& limits,
                     const TimingSettings& settings) {
  settings.check();
  if (waypoints.empty()) throw std::invalid_argument("a timed path needs at least one waypoint");
  for (const auto& q : waypoints)
    if (q.size() != static_cast<Eigen::Index>(limits.size()))
      throw std::invalid_argument("a waypoint's size differs from the limits'");
  checkTimingWork(waypoints, limits, settings);
  std::vector<Configuration> distinct{waypoints.front()};
  for (const auto& q : waypoints) {
    if (q.size() != static_cast<Eigen::Index>(limits.size()))
      throw std::invalid_argument("a waypoint's size differs from the limits'");
    if ((q - distinct.back()).norm() > 0.0) distinct.push_back(q);
  }
  rest_ = distinct.back();
  std::vector<double> velocity, acceleration;
  for (const auto& limit : limits) {
    velocity.push_back(limit.velocity * settings.velocityScale);
    acceleration.push_back(limit.acceleration * settings.accelerationScale);
  }
  std::vector<Configuration> stretch{distinct.front()};
  double time = 0.0;
  const auto close = [&] {
    if (stretch.size() < 2) return;
    Piece piece;
    piece.path = std::make_unique<BlendedPath>(stretch, std::max(settings.blendTolerance, 1e-300));
    piece.profile = timeOptimalProfile(PhasePlane(*piece.path, velocity, acceleration), {settings.timeStep});
    piece.startTime = time;
    time += piece.profile.back().time;
    pieces_.push_back(std::move(piece));
    stretch = {stretch.back()};
  };
  for (std::size_t i = 1; i < distinct.size(); ++i) {
    stretch.push_back(distinct[i]);
    const bool corner = i + 1 < distinct.size();
    if (corner && (settings.blendTolerance == 0.0 || isReversal(distinct[i - 1], distinct[i], distinct[i + 1])))
      close();
  }
  close();
}

double TimedPath::duration() const {
  return pieces_.empty() ? 0.0 : pieces_.back().startTime + pieces_.back().profile.back().time;
}

std::vector<const BlendedPath*> TimedPath::paths() const {
  std::vector<const BlendedPath*> paths;
  for (const auto& piece : pieces_) paths.push_back(piece.path.get());
  return paths;
}

TimedState TimedPath::at(double t) const {
  TimedState state;
  state.time = std::clamp(t, 0.0, duration());
  if (pieces_.empty()) {
    state.position = rest_;
    state.velocity = state.acceleration = Eigen::VectorXd::Zero(rest_.size());
    return state;
  }
  auto piece = std::upper_bound(pieces_.begin(), pieces_.end(), state.time,
                                [](double value, const Piece& p) { return value < p.startTime; });
  if (piece != pieces_.begin()) --piece;
  const auto& profile = piece->profile;
  const double local = std::min(state.time - piece->startTime, profile.back().time);
  auto next = std::upper_bound(profile.begin(), profile.end(), local,
                               [](double value, const PhasePoint& p) { return value < p.time; });
  if (next == profile.end()) next = std::prev(profile.end());
  if (next == profile.begin()) next = std::next(profile.begin());
  const PhasePoint& a = *std::prev(next);
  const PhasePoint& b = *next;
  const double pathAcceleration = (b.speedSquared - a.speedSquared) / (2.0 * (b.s - a.s));
  const double tau = std::clamp(local - a.time, 0.0, b.time - a.time);
  const double startSpeed = std::sqrt(a.speedSquared);
  const double s = std::clamp(a.s + startSpeed * tau + 0.5 * pathAcceleration * tau * tau, a.s, b.s);
  const double speed = std::max(0.0, startSpeed + pathAcceleration * tau);
  // Inside a step, the segment it starts in (a step never crosses a segment boundary).
  const double probe = s > a.s ? s : std::min(b.s, a.s + 1e-12);
  const bool before = probe >= b.s && b.s > a.s;
  state.position = piece->path->position(s, before);
  const Eigen::VectorXd tangent = piece->path->tangent(probe, before);
  state.velocity = tangent * speed;
  state.acceleration = tangent * pathAcceleration + piece->path->curvature(probe, before) * speed * speed;
  return state;
}

}  // namespace pmdplan
