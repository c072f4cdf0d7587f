// The timing's stated ranges and its work bound (TimingBounds, checkSampling): settings out of range
// and timings that would take too long are refused before any integration, and keepsLimits catches
// a timing the phase integration got wrong.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/trajectory/joint_trajectory.hpp"
#include "pmdplan/trajectory/timed_path.hpp"
#include "random_timing_case.hpp"

namespace pmdplan {
namespace {

using test::TimingCase;
using test::timingCase;

std::string timingErrorField(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.field();
  }
  return "(no error)";
}

TEST(TimingBounds, SettingsOutOfRangeAreRefused) {
  const TimingCase c = timingCase(1);
  const auto fieldFor = [&](const TimingSettings& settings) {
    return timingErrorField([&] { TimedPath(c.waypoints, c.limits, settings); });
  };
  // 1e-20 used to give samples needing 27 times the acceleration limit, 1e-12 23 GB.
  for (const double tolerance : {1e-20, 1e-12, 1e-4, 1.5, std::nan("")}) {
    TimingSettings settings;
    settings.blendTolerance = tolerance;
    EXPECT_EQ(fieldFor(settings), "blend-tolerance") << tolerance;
  }
  for (const double scale : {1e-6, 0.0099, 1.01}) {
    TimingSettings settings;
    settings.velocityScale = scale;
    EXPECT_EQ(fieldFor(settings), "velocity-scale") << scale;
    settings.velocityScale = 1.0;
    settings.accelerationScale = scale;
    EXPECT_EQ(fieldFor(settings), "acceleration-scale") << scale;
  }
  for (const double tolerance : {0.0, TimingBounds::kSmallestBlendTolerance, TimingBounds::kLargestBlendTolerance}) {
    TimingSettings settings;
    settings.blendTolerance = tolerance;
    EXPECT_NO_THROW(TimedPath(c.waypoints, c.limits, settings)) << tolerance;
  }
}

TEST(TimingBounds, ATimingThatWouldTakeTooLongIsRefusedBeforeIntegrating) {
  // 100 rad at 0.05 rad/s: 2,000 s of trajectory, 10⁷ integration steps (this used to run for minutes).
  const std::vector<Configuration> waypoints{Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(100.0, 1.0)};
  const std::vector<JointMotionLimit> limits{{"a", 0.05, 1.0}, {"b", 1.0, 1.0}};
  EXPECT_GT(restToRestDuration(waypoints, limits, {}), 1900.0);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(timingErrorField([&] { TimedPath(waypoints, limits, {}); }), "duration");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.1);
  // A smaller time step is more work for the same duration.
  TimingSettings fine;
  fine.timeStep = 1e-300;
  EXPECT_EQ(timingErrorField([&] { TimedPath(timingCase(1).waypoints, timingCase(1).limits, fine); }), "duration");
}

TEST(TimingBounds, TheRestToRestDurationIsTheTimingWithoutBlends) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const TimingCase c = timingCase(seed);
    TimingSettings settings;
    settings.blendTolerance = 0.0;
    const TimedPath timed(c.waypoints, c.limits, settings);
    EXPECT_NEAR(timed.duration(), restToRestDuration(c.waypoints, c.limits, settings), 1e-3 * timed.duration())
        << "seed " << seed;
  }
}

TEST(TimingBounds, SamplingIsBoundedBeforeItStarts) {
  const TimingCase c = timingCase(1);
  const TimedPath timed(c.waypoints, c.limits);
  // 1e-300 used to give a one-point trajectory, 1e-9 bad_alloc.
  for (const double interval : {1e-300, 1e-9, 0.0, -1.0, 2.0, std::nan("")})
    EXPECT_EQ(timingErrorField([&] { sampleTrajectory(timed, {}, interval); }), "sample-interval") << interval;
  EXPECT_EQ(timingErrorField([&] { checkSampling(20.0, 1e-4); }), "sample-interval");  // 200,002 points
  EXPECT_NO_THROW(checkSampling(9.0, 1e-4));
}

TEST(TimingBounds, KeepsLimitsCatchesATimingThePhaseIntegrationGotWrong) {
  // Random path 117 at the default blend tolerance: the integration misses a switching point and
  // one joint's velocity changes 3.5 times faster than its acceleration limit allows (measured);
  // timeCollisionFree then falls back to stopping at every waypoint, which keeps the limits.
  const TimingCase c = timingCase(117);
  EXPECT_FALSE(keepsLimits(TimedPath(c.waypoints, c.limits), c.limits, {}));
  TimingSettings stops;
  stops.blendTolerance = 0.0;
  EXPECT_TRUE(keepsLimits(TimedPath(c.waypoints, c.limits, stops), c.limits, stops));
  EXPECT_TRUE(keepsLimits(TimedPath(timingCase(1).waypoints, timingCase(1).limits), timingCase(1).limits, {}));
}

}  // namespace
}  // namespace pmdplan
