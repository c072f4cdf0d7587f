#include "pmdplan/trajectory/phase_plane.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pmdplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kStill = 1e-12;  ///< a tangent component below this: the joint does not move

}  // namespace

PhasePlane::PhasePlane(const BlendedPath& path, std::vector<double> velocity, std::vector<double> acceleration)
    : path_(path), velocity_(std::move(velocity)), acceleration_(std::move(acceleration)) {}

double PhasePlane::accelerationLimit(double s, bool before) const {
  const auto& segment = path_.segmentAt(s, before);
  if (!segment.circular) return kInfinity;
  const Eigen::VectorXd d = path_.tangent(s, before);
  const Eigen::VectorXd dd = path_.curvature(s, before);
  double limit = kInfinity;
  const Eigen::Index n = d.size();
  for (Eigen::Index i = 0; i < n; ++i) {
    const double ai = acceleration_[static_cast<std::size_t>(i)];
    if (std::abs(d[i]) < kStill) {
      if (std::abs(dd[i]) > 0.0) limit = std::min(limit, std::sqrt(ai / std::abs(dd[i])));
      continue;
    }
    for (Eigen::Index j = i + 1; j < n; ++j) {
      if (std::abs(d[j]) < kStill) continue;
      const double aj = acceleration_[static_cast<std::size_t>(j)];
      const double spread = std::abs(dd[i] / d[i] - dd[j] / d[j]);
      if (spread > 0.0) limit = std::min(limit, std::sqrt((ai / std::abs(d[i]) + aj / std::abs(d[j])) / spread));
    }
  }
  return limit;
}

double PhasePlane::velocityLimit(double s, bool before) const {
  const Eigen::VectorXd d = path_.tangent(s, before);
  double limit = kInfinity;
  for (Eigen::Index i = 0; i < d.size(); ++i)
    if (std::abs(d[i]) >= kStill) limit = std::min(limit, velocity_[static_cast<std::size_t>(i)] / std::abs(d[i]));
  return limit;
}

double PhasePlane::velocityLimitSlope(double s, bool before) const {
  if (!path_.segmentAt(s, before).circular) return 0.0;
  const Eigen::VectorXd d = path_.tangent(s, before);
  const Eigen::VectorXd dd = path_.curvature(s, before);
  double limit = kInfinity;
  double slope = 0.0;
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (std::abs(d[i]) < kStill) continue;
    const double value = velocity_[static_cast<std::size_t>(i)] / std::abs(d[i]);
    if (value < limit) {
      limit = value;
      slope = -velocity_[static_cast<std::size_t>(i)] * dd[i] / (d[i] * std::abs(d[i]));
    }
  }
  return slope;
}

double PhasePlane::limit(double s, bool before) const {
  return std::min(accelerationLimit(s, before), velocityLimit(s, before));
}

std::pair<double, double> PhasePlane::accelerationRange(double s, double speed, bool before) const {
  const Eigen::VectorXd d = path_.tangent(s, before);
  const Eigen::VectorXd dd = path_.curvature(s, before);
  double lowest = -kInfinity;
  double highest = kInfinity;
  const double squared = speed * speed;
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (std::abs(d[i]) < kStill) continue;
    const double a = acceleration_[static_cast<std::size_t>(i)];
    const double low = (-a - dd[i] * squared) / d[i];
    const double high = (a - dd[i] * squared) / d[i];
    lowest = std::max(lowest, std::min(low, high));
    highest = std::min(highest, std::max(low, high));
  }
  return {lowest, highest};
}

}  // namespace pmdplan
