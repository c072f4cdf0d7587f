#pragma once
// A random path (2-7 joints, 2-9 waypoints in [-2, 2] rad) under random velocity and acceleration
// limits: the timing tests' shared input, the same for the same seed.
#include <cstdint>
#include <string>
#include <vector>

#include "pmdplan/core/random_source.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/trajectory/joint_motion_limits.hpp"

namespace pmdplan::test {

struct TimingCase {
  std::vector<Configuration> waypoints;
  std::vector<JointMotionLimit> limits;
};

inline TimingCase timingCase(std::uint64_t seed) {
  RandomSource random(seed);
  const int dof = 2 + static_cast<int>(random.uniform01() * 6);
  const int count = 2 + static_cast<int>(random.uniform01() * 8);
  TimingCase c;
  for (int j = 0; j < dof; ++j)
    c.limits.push_back({"j" + std::to_string(j), random.uniform(0.5, 7.0), random.uniform(1.0, 20.0)});
  for (int k = 0; k < count; ++k) {
    Configuration q(dof);
    for (int j = 0; j < dof; ++j) q[j] = random.uniform(-2.0, 2.0);
    c.waypoints.push_back(q);
  }
  return c;
}

}  // namespace pmdplan::test
