#include "pmdplan/trajectory/timed_path.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

void TimingSettings::check() const {
  if (!(std::isfinite(blendTolerance) && blendTolerance >= 0.0))
    throw InputError("", "blend-tolerance", "expected a number of radians >= 0");
  if (!(velocityScale > 0.0 && velocityScale <= 1.0))
    throw InputError("", "velocity-scale", "expected a fraction in (0, 1]");
  if (!(accelerationScale > 0.0 && accelerationScale <= 1.0))
    throw InputError("", "acceleration-scale", "expected a fraction in (0, 1]");
  if (!(timeStep > 0.0 && timeStep <= 0.1)) throw InputError("", "time-step", "expected seconds in (0, 0.1]");
}

TimedPath::TimedPath(const std::vector<Configuration>& waypoints, const std::vector<JointMotionLimit>& limits,
                     const TimingSettings& settings) {
  settings.check();
  if (waypoints.empty()) throw std::invalid_argument("a timed path needs at least one waypoint");
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
