#include "pmdplan/trajectory/joint_trajectory.hpp"

#include <cmath>
#include <stdexcept>

namespace pmdplan {

JointTrajectory sampleTrajectory(const TimedPath& timed, std::vector<std::string> jointNames, double interval) {
  if (!(interval > 0.0)) throw std::invalid_argument("the sampling interval must be positive");
  JointTrajectory trajectory{std::move(jointNames), {}};
  const double duration = timed.duration();
  const auto steps = static_cast<long>(std::floor(duration / interval));
  for (long k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) * interval;
    if (k > 0 && duration - t < 1e-9) break;
    trajectory.points.push_back(timed.at(t));
  }
  trajectory.points.push_back(timed.at(duration));
  return trajectory;
}

}  // namespace pmdplan
