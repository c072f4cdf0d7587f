// Time-optimal parameterisation: random paths under random limits, resampled at 1 ms, never
// exceed a joint's velocity or acceleration limit, stay within the blending tolerance of the
// polyline, start and end at rest on the first and last waypoint, and are as fast as the
// closed-form optimum where there is one (a single straight segment).
#include "pmdplan/trajectory/timed_path.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/trajectory/joint_trajectory.hpp"
#include "random_timing_case.hpp"
#include "support/sanitizer_build.hpp"

namespace pmdplan {
namespace {

double distanceToSegment(const Eigen::VectorXd& q, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::VectorXd ab = b - a;
  const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - q).norm();
}

double distanceToPolyline(const Eigen::VectorXd& q, const std::vector<Configuration>& points) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < points.size(); ++i) best = std::min(best, distanceToSegment(q, points[i - 1], points[i]));
  return best;
}

using test::TimingCase;
using test::timingCase;

TEST(TimedPath, RandomPathsKeepEveryLimitAndTheBlendingTolerance) {
  // The profile's acceleration is chosen at one end of each 0.2 ms integration step: inside a step
  // the joints' accelerations drift by at most a few parts in a thousand, and along an arc the
  // velocity between two points on the velocity limit curve by a few parts in a hundred thousand.
  constexpr double kVelocitySlack = 1e-4, kAccelerationSlack = 5e-3;
  for (std::uint64_t seed = 1; seed <= test::trials(60, 15); ++seed) {
    const TimingCase c = timingCase(seed);
    TimingSettings settings;
    settings.blendTolerance = seed % 3 == 0 ? 0.0 : 0.05 * static_cast<double>(seed % 5 + 1);
    const TimedPath timed(c.waypoints, c.limits, settings);
    ASSERT_GT(timed.duration(), 0.0) << "seed " << seed;
    double worstVelocity = 0.0, worstAcceleration = 0.0, worstDeviation = 0.0;
    TimedState previous = timed.at(0.0);
    const auto steps = static_cast<long>(timed.duration() / 0.001);
    for (long k = 0; k <= steps; ++k) {
      const double t = static_cast<double>(k) * 0.001;
      const TimedState state = timed.at(t);
      const double dt = state.time - previous.time;
      for (std::size_t j = 0; j < c.limits.size(); ++j) {
        const auto i = static_cast<Eigen::Index>(j);
        worstVelocity = std::max(worstVelocity, std::abs(state.velocity[i]) / c.limits[j].velocity);
        worstAcceleration = std::max(worstAcceleration, std::abs(state.acceleration[i]) / c.limits[j].acceleration);
        // The reported velocity is the positions' real rate: over 1 ms no joint moves farther than it allows.
        EXPECT_LE(std::abs(state.position[i] - previous.position[i]),
                  c.limits[j].velocity * dt * (1.0 + kVelocitySlack) + 1e-12)
            << "seed " << seed << " joint " << j << " t " << t;
      }
      worstDeviation = std::max(worstDeviation, distanceToPolyline(state.position, c.waypoints));
      previous = state;
    }
    EXPECT_LE(worstVelocity, 1.0 + kVelocitySlack) << "seed " << seed;
    EXPECT_LE(worstAcceleration, 1.0 + kAccelerationSlack) << "seed " << seed;
    EXPECT_LE(worstDeviation, settings.blendTolerance + 1e-9) << "seed " << seed;
    const TimedState start = timed.at(0.0), end = timed.at(timed.duration());
    EXPECT_LT((start.position - c.waypoints.front()).norm(), 1e-12);
    EXPECT_LT((end.position - c.waypoints.back()).norm(), 1e-9);
    EXPECT_LT(start.velocity.norm() + end.velocity.norm(), 1e-9);
  }
}

TEST(TimedPath, AStraightSegmentTakesTheTrapezoidalOptimum) {
  // One joint-space line: the fastest motion accelerates at the binding joint's limit, cruises at
  // its velocity limit and brakes; T = D/v + v/a for the path-space limits v and a.
  const std::vector<JointMotionLimit> limits{{"a", 2.0, 4.0}, {"b", 1.0, 10.0}};
  for (double length : {0.05, 0.3, 1.0, 3.0}) {
    const Eigen::Vector2d direction = Eigen::Vector2d(3.0, 4.0).normalized();
    const std::vector<Configuration> waypoints{Eigen::Vector2d(0.1, -0.2),
                                               Eigen::Vector2d(0.1, -0.2) + length * direction};
    const TimedPath timed(waypoints, limits);
    const double v = std::min(2.0 / direction[0], 1.0 / direction[1]);
    const double a = std::min(4.0 / direction[0], 10.0 / direction[1]);
    const double optimum = length >= v * v / a ? length / v + v / a : 2.0 * std::sqrt(length / a);
    EXPECT_NEAR(timed.duration(), optimum, 2e-3 * optimum) << "length " << length;
  }
}

TEST(TimedPath, AReversalIsPassedAtRest) {
  const std::vector<JointMotionLimit> limits{{"a", 1.0, 2.0}};
  Configuration p0(1), p1(1), p2(1);
  p0 << 0.0;
  p1 << 1.0;
  p2 << 0.5;
  const TimedPath timed({p0, p1, p2}, limits);
  double farthest = 0.0, speedThere = 1.0;
  for (double t = 0.0; t <= timed.duration(); t += 0.0005) {
    const TimedState state = timed.at(t);
    if (state.position[0] > farthest) {
      farthest = state.position[0];
      speedThere = std::abs(state.velocity[0]);
    }
  }
  EXPECT_NEAR(farthest, 1.0, 1e-6);
  EXPECT_LT(speedThere, 2e-3);
}

TEST(JointTrajectory, SamplesAtTheIntervalAndEndsAtTheDuration) {
  const TimingCase c = timingCase(7);
  const TimedPath timed(c.waypoints, c.limits);
  const JointTrajectory trajectory = sampleTrajectory(timed, {}, 0.01);
  ASSERT_GE(trajectory.points.size(), 2u);
  for (std::size_t k = 1; k + 1 < trajectory.points.size(); ++k)
    EXPECT_NEAR(trajectory.points[k].time - trajectory.points[k - 1].time, 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(trajectory.points.back().time, timed.duration());
  EXPECT_THROW(sampleTrajectory(timed, {}, 0.0), InputError);
}

}  // namespace
}  // namespace pmdplan
