#pragma once
// Configurations for the fast-vs-exact tests: uniform in the joint limits, near the task's start
// and goal, and near its straight start-goal segment, so many lie near contact or in collision.
// Normals by Box-Muller from RandomSource (std:: distributions differ between libraries).
#include <algorithm>
#include <cmath>

#include "pmdplan/core/random_source.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan::testing {

inline double normal(RandomSource& random) {
  const double u1 = 1.0 - random.uniform01();  // (0, 1]
  const double u2 = random.uniform01();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

/// Kind 0: uniform; 1: near start or goal; 2: near the straight start-goal segment. The spread is
/// a fraction of each joint's range.
inline Configuration taskConfiguration(const Task& task, RandomSource& random, int kind, double spread = 0.05) {
  const auto& joints = task.robot->activeJoints();
  const int dof = task.robot->dof();
  Configuration q(dof);
  const double t = random.uniform01();
  const bool nearGoal = random.uniform01() < 0.5;
  for (int i = 0; i < dof; ++i) {
    const auto& j = joints[static_cast<std::size_t>(i)];
    const double range = j.upper - j.lower;
    double value;
    if (kind == 0)
      value = random.uniform(j.lower, j.upper);
    else if (kind == 1)
      value = (nearGoal ? task.goal[i] : task.start[i]) + spread * range * normal(random);
    else
      value = task.start[i] + t * (task.goal[i] - task.start[i]) + spread * range * normal(random);
    q[i] = std::clamp(value, j.lower, j.upper);
  }
  return q;
}

}  // namespace pmdplan::testing
