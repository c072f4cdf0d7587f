#include "pmdplan/trajectory/blended_path.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pmdplan {
namespace {

constexpr double kCollinear = 1e-9;  ///< corners flatter than this (rad) need no blend
constexpr double kReversal = 1e-6;   ///< corners within this of 180° cannot be blended

double cornerAngle(const Eigen::VectorXd& in, const Eigen::VectorXd& out) {
  return std::acos(std::clamp(in.dot(out), -1.0, 1.0));
}

}  // namespace

bool isReversal(const Configuration& before, const Configuration& at, const Configuration& after) {
  const Eigen::VectorXd in = at - before;
  const Eigen::VectorXd out = after - at;
  if (in.norm() == 0.0 || out.norm() == 0.0) return false;
  return cornerAngle(in.normalized(), out.normalized()) > M_PI - kReversal;
}

BlendedPath::BlendedPath(const std::vector<Configuration>& waypoints, double blendTolerance) {
  if (waypoints.size() < 2) throw std::invalid_argument("a blended path needs at least two waypoints");
  if (!(blendTolerance > 0.0)) throw std::invalid_argument("the blending tolerance must be positive");
  const std::size_t n = waypoints.size();
  for (std::size_t i = 1; i < n; ++i)
    if ((waypoints[i] - waypoints[i - 1]).norm() == 0.0)
      throw std::invalid_argument("two consecutive waypoints are equal");
  // Each interior corner's blend reaches `reach[i]` along both neighbouring segments.
  std::vector<double> reach(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Eigen::VectorXd in = waypoints[i] - waypoints[i - 1];
    const Eigen::VectorXd out = waypoints[i + 1] - waypoints[i];
    const double angle = cornerAngle(in.normalized(), out.normalized());
    if (angle > M_PI - kReversal) throw std::invalid_argument("a corner reverses the direction and cannot be blended");
    if (angle < kCollinear) continue;
    const double half = angle / 2.0;
    // The arc's distance from the corner is r / cos(half) - r; reach = tolerance·sin/(1 - cos) makes it equal the
    // tolerance.
    reach[i] = std::min({in.norm() / 2.0, out.norm() / 2.0, blendTolerance * std::sin(half) / (1.0 - std::cos(half))});
  }
  Eigen::VectorXd cursor = waypoints.front();
  for (std::size_t i = 1; i < n; ++i) {
    const Eigen::VectorXd in = (waypoints[i] - waypoints[i - 1]).normalized();
    const Eigen::VectorXd arcStart = waypoints[i] - reach[i] * in;
    if ((arcStart - cursor).norm() > 0.0) addLinear(cursor, arcStart);
    cursor = arcStart;
    if (i + 1 == n || reach[i] == 0.0) {
      cursor = i + 1 == n ? waypoints[i] : arcStart;
      continue;
    }
    const Eigen::VectorXd out = (waypoints[i + 1] - waypoints[i]).normalized();
    const double angle = cornerAngle(in, out);
    const double radius = reach[i] / std::tan(angle / 2.0);
    const Eigen::VectorXd centre = waypoints[i] + (out - in).normalized() * (radius / std::cos(angle / 2.0));
    addArc(centre, (arcStart - centre).normalized(), in, radius, angle);
    cursor = waypoints[i] + reach[i] * out;
  }
  for (std::size_t k = 1; k < segments_.size(); ++k) switchingPoints_.push_back({segments_[k].start, true});
  for (const Segment& segment : segments_) {
    if (!segment.circular) continue;
    const double angle = segment.length / segment.radius;
    for (Eigen::Index j = 0; j < segment.x.size(); ++j) {
      // tangent_j(θ) = -x_j sin θ + y_j cos θ vanishes at θ = atan2(y_j, x_j) + kπ.
      double theta = std::atan2(segment.y[j], segment.x[j]);
      if (theta < 0.0) theta += M_PI;
      if (theta > 0.0 && theta < angle) switchingPoints_.push_back({segment.start + theta * segment.radius, false});
    }
  }
  std::sort(switchingPoints_.begin(), switchingPoints_.end(),
            [](const SwitchingPoint& a, const SwitchingPoint& b) { return a.s < b.s; });
}

void BlendedPath::addLinear(const Eigen::VectorXd& from, const Eigen::VectorXd& to) {
  Segment segment;
  segment.start = length_;
  segment.length = (to - from).norm();
  segment.origin = from;
  segment.x = (to - from) / segment.length;
  segments_.push_back(segment);
  length_ += segment.length;
}

void BlendedPath::addArc(const Eigen::VectorXd& centre, const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                         double radius, double angle) {
  Segment segment;
  segment.start = length_;
  segment.length = radius * angle;
  segment.circular = true;
  segment.origin = centre;
  segment.x = x;
  segment.y = y;
  segment.radius = radius;
  segments_.push_back(segment);
  length_ += segment.length;
}

const BlendedPath::Segment& BlendedPath::segmentAt(double s, bool before) const {
  const auto after = std::upper_bound(segments_.begin(), segments_.end(), s,
                                      [](double value, const Segment& segment) { return value < segment.start; });
  auto it = after == segments_.begin() ? after : std::prev(after);
  if (before && it != segments_.begin() && s <= it->start) --it;
  return *it;
}

Configuration BlendedPath::position(double s, bool before) const {
  const Segment& segment = segmentAt(s, before);
  const double local = std::clamp(s - segment.start, 0.0, segment.length);
  if (!segment.circular) return segment.origin + local * segment.x;
  const double theta = local / segment.radius;
  return segment.origin + segment.radius * (segment.x * std::cos(theta) + segment.y * std::sin(theta));
}

Eigen::VectorXd BlendedPath::tangent(double s, bool before) const {
  const Segment& segment = segmentAt(s, before);
  if (!segment.circular) return segment.x;
  const double theta = std::clamp(s - segment.start, 0.0, segment.length) / segment.radius;
  return segment.y * std::cos(theta) - segment.x * std::sin(theta);
}

Eigen::VectorXd BlendedPath::curvature(double s, bool before) const {
  const Segment& segment = segmentAt(s, before);
  if (!segment.circular) return Eigen::VectorXd::Zero(segment.x.size());
  const double theta = std::clamp(s - segment.start, 0.0, segment.length) / segment.radius;
  return -(segment.x * std::cos(theta) + segment.y * std::sin(theta)) / segment.radius;
}

}  // namespace pmdplan
