#include "pmdplan/trajectory/phase_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace pmdplan {
namespace {

constexpr double kProbe = 1e-6;     ///< path length probed on each side of a candidate switching point
constexpr double kScanStep = 1e-3;  ///< path length between probes of the velocity limit curve
constexpr double kSlack = 1e-9;     ///< relative slack when comparing with a limit curve

/// A switching point and the accelerations to leave it with: backward (before) and forward (after).
/// At an arc's tangent-zero point the limit curve is a smooth minimum and both are 0 there.
struct Switch {
  PhasePoint point;
  double before = 0.0;
  double after = 0.0;
};

class Integrator {
 public:
  Integrator(const PhasePlane& plane, const PhaseProfileSettings& settings)
      : plane_(plane), path_(plane.path()), dt_(settings.timeStep), maxSteps_(settings.maxSteps) {
    for (const auto& point : path_.switchingPoints())
      if (point.discontinuity) discontinuities_.push_back(point.s);
  }

  void countStep() {
    if (++steps_ > maxSteps_)
      throw std::runtime_error("time-optimal parameterisation: more than " + std::to_string(maxSteps_) +
                               " integration steps");
  }

  std::vector<PhasePoint> run() {
    points_ = {{0.0, 0.0, 0.0}};
    while (!forward()) {
      const auto next = nextSwitchingPoint(points_.back().s);
      if (!next) break;
      backward(next->point, next->before);
      firstForward_ = next->after;
      leavingSteps_ = 3;
    }
    backward({path_.length(), 0.0, 0.0}, std::nullopt);
    for (std::size_t k = 1; k < points_.size(); ++k) {
      const double speeds = std::sqrt(points_[k - 1].speedSquared) + std::sqrt(points_[k].speedSquared);
      points_[k].time = points_[k - 1].time + (speeds > 0.0 ? 2.0 * (points_[k].s - points_[k - 1].s) / speeds : 0.0);
    }
    return points_;
  }

 private:
  double nextDiscontinuity(double s) const {
    const auto it = std::upper_bound(discontinuities_.begin(), discontinuities_.end(), s + 1e-12);
    return it == discontinuities_.end() ? std::numeric_limits<double>::infinity() : *it;
  }
  double previousDiscontinuity(double s) const {
    const auto it = std::lower_bound(discontinuities_.begin(), discontinuities_.end(), s - 1e-12);
    return it == discontinuities_.begin() ? -std::numeric_limits<double>::infinity() : *std::prev(it);
  }
  /// The limit curve at a point a step was clamped to: at a discontinuity, the lower of both sides.
  double limitAt(double s, bool atDiscontinuity) const {
    return atDiscontinuity ? std::min(plane_.limit(s, true), plane_.limit(s, false)) : plane_.limit(s);
  }
  bool velocityBinds(double s, bool before = false) const {
    return plane_.velocityLimit(s, before) <= plane_.accelerationLimit(s, before);
  }

  /// Forward at the largest acceleration (following the velocity limit curve where it is lower
  /// and reachable). True when the end is reached; false at a limit curve it cannot follow.
  bool forward() {
    const double length = path_.length();
    while (true) {
      countStep();
      const PhasePoint p = points_.back();
      const double speed = std::sqrt(p.speedSquared);
      auto [lowest, highest] = plane_.accelerationRange(p.s, speed);
      if (firstForward_) {
        lowest = highest = *firstForward_;
        firstForward_.reset();
      } else if (lowest > highest) {
        // On the acceleration limit curve up to rounding (just after a switching point): the
        // one acceleration there; farther above it the trajectory has hit the curve.
        if (speed > plane_.accelerationLimit(p.s) * (1.0 + 1e-6)) return false;
        lowest = highest = 0.5 * (lowest + highest);
      }
      const double discontinuity = nextDiscontinuity(p.s);
      // Near a limit curve the feasible range of s̈ narrows quickly: the step is halved until its
      // acceleration also holds at its end (at most 64 times shorter).
      double step = dt_;
      double s = p.s;
      for (int halving = 0; halving <= 6; ++halving, step *= 0.5) {
        const double nextSpeed = std::max(0.0, speed + highest * step);
        s = std::min({p.s + step * 0.5 * (speed + nextSpeed), discontinuity, length});
        const auto end =
            plane_.accelerationRange(s, std::sqrt(std::max(0.0, p.speedSquared + 2.0 * highest * (s - p.s))));
        if (end.first > end.second || highest <= end.second * (1.0 + 1e-9) + 1e-12) break;
      }
      if (s <= p.s) return false;
      const bool clamped = s >= discontinuity;
      const double squared = p.speedSquared + 2.0 * highest * (s - p.s);
      const double limit = limitAt(s, clamped);
      if (squared > limit * limit) {
        const bool follow = velocityBinds(s, clamped) && velocityBinds(s, false) &&
                            p.speedSquared + 2.0 * lowest * (s - p.s) <= limit * limit;
        if (follow) {
          points_.push_back({s, limit * limit, 0.0});
          if (s >= length) return true;
          continue;
        }
        double inside = p.s, outside = s;
        for (int i = 0; i < 60; ++i) {
          const double middle = 0.5 * (inside + outside);
          const double value = plane_.limit(middle);
          (p.speedSquared + 2.0 * highest * (middle - p.s) <= value * value ? inside : outside) = middle;
        }
        if (inside > p.s) {
          points_.push_back({inside, p.speedSquared + 2.0 * highest * (inside - p.s), 0.0});
        } else if (leavingSteps_ > 0) {
          // Leaving a switching point tangent to the curve: the curve bends below the tangent, so
          // the first steps go along the curve itself.
          --leavingSteps_;
          points_.push_back({s, limit * limit, 0.0});
          if (s >= length) return true;
          continue;
        }
        return false;
      }
      points_.push_back({s, squared, 0.0});
      leavingSteps_ = 0;
      if (s >= length) return true;
    }
  }

  /// Can the trajectory leave (s, speed) backward at the smallest and forward at the largest
  /// acceleration without crossing the limit curve?
  bool isSwitchingPoint(double s, double speed) const {
    const auto before = plane_.accelerationRange(s, speed, true);
    const auto after = plane_.accelerationRange(s, speed, false);
    const double back = speed * speed - 2.0 * before.first * kProbe;
    const double ahead = speed * speed + 2.0 * after.second * kProbe;
    const double limitBack = plane_.limit(std::max(0.0, s - kProbe));
    const double limitAhead = plane_.limit(std::min(path_.length(), s + kProbe));
    return back <= limitBack * limitBack * (1.0 + kSlack) && ahead <= limitAhead * limitAhead * (1.0 + kSlack);
  }

  /// On the velocity limit curve (it is below the acceleration one) and falling there faster than
  /// the largest deceleration lets a trajectory follow (s̈_min > ṡ · d/ds ṡ_max).
  bool onVelocityCurve(double s) const { return velocityBinds(s); }
  bool tooSteep(double s) const {
    const double speed = plane_.velocityLimit(s);
    return plane_.accelerationRange(s, speed).first > plane_.velocityLimitSlope(s) * speed;
  }

  /// A point where an arc's joint tangent vanishes is a switching point where it is a local
  /// minimum of the acceleration limit curve (as in MoveIt's implementation of the method).
  bool isCurveMinimum(double s) const {
    const double here = plane_.accelerationLimit(s);
    return plane_.accelerationLimit(std::max(0.0, s - kProbe)) >= here &&
           plane_.accelerationLimit(std::min(path_.length(), s + kProbe)) >= here;
  }

  /// Where the acceleration limit curve binds, the one feasible s̈ there against the curve's slope:
  /// negative where a trajectory along the curve would rise above it going forward (only a
  /// backward one can leave), positive where it would rise above it going backward.
  double curveGap(double s) const {
    const double h = 1e-7;
    const double low = std::max(0.0, s - h), high = std::min(path_.length(), s + h);
    const double slope = (plane_.accelerationLimit(high) - plane_.accelerationLimit(low)) / (high - low);
    const double speed = plane_.accelerationLimit(s);
    const auto range = plane_.accelerationRange(s, speed * (1.0 - 1e-9));
    return slope - 0.5 * (range.first + range.second) / speed;
  }

  /// The first point in (from, end) of an arc where the acceleration limit curve binds and a
  /// trajectory can leave it both ways (curveGap turns from negative to positive): the switching
  /// points of the curve's smooth stretches, found by scanning and bisection.
  std::optional<Switch> nextTangentPoint(double from, double end) const {
    for (const auto& segment : path_.segments()) {
      if (!segment.circular || segment.start + segment.length <= from || segment.start >= end) continue;
      const double first = std::max(from, segment.start) + 1e-9,
                   last = std::min(end, segment.start + segment.length) - 1e-9;
      const auto binds = [&](double s) { return !velocityBinds(s); };
      double previous = first;
      bool previousNegative = binds(first) && curveGap(first) < 0.0;
      for (double s = first + kScanStep; previous < last; s += kScanStep) {
        s = std::min(s, last);
        const bool bound = binds(s);
        const double gap = bound ? curveGap(s) : 0.0;
        if (previousNegative && bound && gap >= 0.0) {
          double low = previous, high = s;
          for (int i = 0; i < 50; ++i) {
            const double middle = 0.5 * (low + high);
            (binds(middle) && curveGap(middle) < 0.0 ? low : high) = middle;
          }
          const double speed = plane_.accelerationLimit(high);
          const auto range = plane_.accelerationRange(high, speed * (1.0 - 1e-9));
          const double u = 0.5 * (range.first + range.second);
          return Switch{{high, speed * speed, 0.0}, u, u};
        }
        previousNegative = bound && gap < 0.0;
        previous = s;
      }
    }
    return std::nullopt;
  }

  std::optional<Switch> nextSwitchingPoint(double from) const {
    std::optional<Switch> found;
    for (const auto& point : path_.switchingPoints()) {
      if (point.s <= from + 1e-9) continue;
      if (point.discontinuity) {
        const double speed = std::min(plane_.limit(point.s, true), plane_.limit(point.s, false));
        if (!isSwitchingPoint(point.s, speed)) continue;
        found = Switch{{point.s, speed * speed, 0.0},
                       plane_.accelerationRange(point.s, speed, true).first,
                       plane_.accelerationRange(point.s, speed, false).second};
      } else {
        const double speed = plane_.accelerationLimit(point.s);
        if (speed > plane_.velocityLimit(point.s) || !isCurveMinimum(point.s)) continue;
        found = Switch{{point.s, speed * speed, 0.0}, 0.0, 0.0};
      }
      break;
    }
    if (const auto tangent = nextTangentPoint(from, found ? found->point.s : path_.length())) found = tangent;
    // The velocity limit curve: the first place after a stretch where it falls too steeply to
    // follow at which it can be followed again.
    const double end = found ? found->point.s : path_.length();
    double s = from;
    while (s < end) {
      while (s < end && !(onVelocityCurve(s) && tooSteep(s))) s += kScanStep;
      while (s < end && onVelocityCurve(s) && tooSteep(s)) s += kScanStep;
      if (s >= end || !onVelocityCurve(s)) continue;
      double low = std::max(from, s - kScanStep), high = s;
      for (int i = 0; i < 50; ++i) {
        const double middle = 0.5 * (low + high);
        (tooSteep(middle) ? low : high) = middle;
      }
      const double speed = plane_.velocityLimit(high);
      const auto range = plane_.accelerationRange(high, speed);
      if (high > from + 1e-9) return Switch{{high, speed * speed, 0.0}, range.first, range.second};
    }
    return found;
  }

  double forwardSpeedSquaredAt(double s) const {
    const auto it = std::lower_bound(points_.begin(), points_.end(), s,
                                     [](const PhasePoint& p, double value) { return p.s < value; });
    if (it == points_.begin()) return it->speedSquared;
    if (it == points_.end()) return points_.back().speedSquared;
    const auto& a = *std::prev(it);
    const auto& b = *it;
    return a.speedSquared + (b.speedSquared - a.speedSquared) * (s - a.s) / (b.s - a.s);
  }

  /// Backward from `start` at the smallest acceleration until it meets the forward trajectory,
  /// which it then replaces from the meeting point on.
  void backward(const PhasePoint& start, std::optional<double> firstAcceleration) {
    std::vector<PhasePoint> curve{start};
    while (true) {
      countStep();
      const PhasePoint c = curve.back();
      const double speed = std::sqrt(c.speedSquared);
      const double lowest = firstAcceleration ? *firstAcceleration : plane_.accelerationRange(c.s, speed, true).first;
      firstAcceleration.reset();
      const double discontinuity = previousDiscontinuity(c.s);
      double step = dt_;
      double s = c.s;
      for (int halving = 0; halving <= 6; ++halving, step *= 0.5) {
        const double earlierSpeed = speed - lowest * step;
        s = std::max({c.s - step * 0.5 * (speed + earlierSpeed), discontinuity, 0.0});
        const auto start =
            plane_.accelerationRange(s, std::sqrt(std::max(0.0, c.speedSquared - 2.0 * lowest * (c.s - s))));
        if (start.first > start.second || lowest <= start.second * (1.0 + 1e-9) + 1e-12) break;
      }
      const bool clamped = s <= discontinuity;
      double squared = c.speedSquared - 2.0 * lowest * (c.s - s);
      const double limit = limitAt(s, clamped);
      squared = std::min(squared, limit * limit);
      if (s <= points_.back().s && squared >= forwardSpeedSquaredAt(s)) {
        splice(curve, {s, squared, 0.0});
        return;
      }
      if (s <= 0.0)
        throw std::runtime_error("time-optimal parameterisation: the backward integration missed the forward one");
      curve.push_back({s, squared, 0.0});
    }
  }

  /// The meeting point of the backward step from `earlier` to curve.back() with the forward
  /// trajectory (both have ṡ² linear in s between their points), then the backward curve after it.
  void splice(const std::vector<PhasePoint>& curve, const PhasePoint& earlier) {
    const PhasePoint& later = curve.back();
    const auto backwardAt = [&](double s) {
      return earlier.speedSquared +
             (later.speedSquared - earlier.speedSquared) * (s - earlier.s) / (later.s - earlier.s);
    };
    const auto gap = [&](double s) { return backwardAt(s) - forwardSpeedSquaredAt(s); };
    std::vector<double> breaks{earlier.s};
    const double right = std::min(later.s, points_.back().s);
    for (const auto& p : points_)
      if (p.s > earlier.s && p.s < right) breaks.push_back(p.s);
    breaks.push_back(right);
    double meet = earlier.s;
    for (std::size_t k = breaks.size() - 1; k > 0; --k) {
      const double a = breaks[k - 1], b = breaks[k];
      const double ga = gap(a), gb = gap(b);
      if (ga >= 0.0) {
        meet = gb >= 0.0 ? b : a + (b - a) * ga / (ga - gb);
        break;
      }
    }
    const double meetSquared = std::max(0.0, forwardSpeedSquaredAt(meet));
    while (!points_.empty() && points_.back().s >= meet) points_.pop_back();
    points_.push_back({meet, meetSquared, 0.0});
    for (auto it = curve.rbegin(); it != curve.rend(); ++it)
      if (it->s > meet) points_.push_back(*it);
  }

  const PhasePlane& plane_;
  const BlendedPath& path_;
  double dt_;
  long maxSteps_;
  long steps_ = 0;
  std::vector<double> discontinuities_;
  std::vector<PhasePoint> points_;
  std::optional<double> firstForward_;
  int leavingSteps_ = 0;
};

}  // namespace

std::vector<PhasePoint> timeOptimalProfile(const PhasePlane& plane, const PhaseProfileSettings& settings) {
  if (!(settings.timeStep > 0.0)) throw std::invalid_argument("the integration time step must be positive");
  return Integrator(plane, settings).run();
}

}  // namespace pmdplan
