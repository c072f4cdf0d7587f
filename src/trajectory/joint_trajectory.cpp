#include "pmdplan/trajectory/joint_trajectory.hpp"

#include <cmath>
#include <cstdio>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

void checkSampling(double duration, double interval) {
  if (!(interval >= kSmallestSampleInterval && interval <= kLargestSampleInterval))
    throw InputError("", "sample-interval", "expected seconds from 0.0001 to 1");
  if (!(duration / interval + 2.0 <= kMaxTrajectorySamples)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "%.4g s of trajectory every %g s is %.3g points, more than %g; expected an interval of at least "
                  "%.3g s",
                  duration, interval, duration / interval + 2.0, kMaxTrajectorySamples,
                  duration / (kMaxTrajectorySamples - 2.0));
    throw InputError("", "sample-interval", text);
  }
}

JointTrajectory sampleTrajectory(const TimedPath& timed, std::vector<std::string> jointNames, double interval) {
  checkSampling(timed.duration(), interval);
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
