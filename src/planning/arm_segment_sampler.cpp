#include "pmdplan/planning/arm_segment_sampler.hpp"

#include <algorithm>
#include <cmath>

namespace pmdplan {

ArmSegmentSampler::ArmSegmentSampler(const PlanningSpace& space, const Configuration& start, const Configuration& goal)
    : armIndices_(space.armIndices) {
  const auto n = static_cast<Eigen::Index>(armIndices_.size());
  startUnit_.resize(n);
  goalUnit_.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const int i = armIndices_[static_cast<std::size_t>(k)];
    const JointLimit& joint = space.joints[static_cast<std::size_t>(i)];
    armLimits_.push_back(joint);
    startUnit_[k] = joint.normalise(start[i]);
    goalUnit_[k] = joint.normalise(goal[i]);
  }
  double sum = 0.0;  // index order, not Eigen's SIMD-width-dependent norm(): same STEPS everywhere
  for (Eigen::Index k = 0; k < n; ++k) sum += (goalUnit_[k] - startUnit_[k]) * (goalUnit_[k] - startUnit_[k]);
  segmentLength_ = std::sqrt(sum);
}

void ArmSegmentSampler::draw(double step, double halfSize, UnitPoints& points, Configuration& q) const {
  std::vector<double> point(armIndices_.size());
  points.next(PointStream::Arm, dimension(), point.data());
  for (std::size_t k = 0; k < armIndices_.size(); ++k) {
    const auto e = static_cast<Eigen::Index>(k);
    const double centre = startUnit_[e] + step * (goalUnit_[e] - startUnit_[e]);
    const double low = std::max(0.0, centre - halfSize);
    const double high = std::min(1.0, centre + halfSize);
    const JointLimit& joint = armLimits_[k];
    // Rounding in denormalise may step a hair past a limit; the limits themselves are valid.
    q[armIndices_[k]] = std::clamp(joint.denormalise(low + (high - low) * point[k]), joint.lower, joint.upper);
  }
}

bool ArmSegmentSampler::sample(double step, double halfSize, UnitPoints& points, StateValidator& validator,
                               Configuration& q, int maxTrials) const {
  for (int trial = 0; trial < maxTrials; ++trial) {
    draw(step, halfSize, points, q);
    if (validator.isArmValid(q)) return true;
  }
  return false;
}

}  // namespace pmdplan
