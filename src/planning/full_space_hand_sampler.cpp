#include "pmdplan/planning/full_space_hand_sampler.hpp"

#include <algorithm>

namespace pmdplan {

FullSpaceHandSampler::FullSpaceHandSampler(const PlanningSpace& space) : handIndices_(space.handIndices) {
  for (const int i : handIndices_) handLimits_.push_back(space.joints[static_cast<std::size_t>(i)]);
}

void FullSpaceHandSampler::sample(int /*dimension*/, UnitPoints& points, Configuration& q) const {
  std::vector<double> point(handIndices_.size());
  points.next(PointStream::Hand, maxDimension(), point.data());
  for (std::size_t k = 0; k < handIndices_.size(); ++k) {
    const JointLimit& joint = handLimits_[k];
    q[handIndices_[k]] = std::min(joint.lower + (joint.upper - joint.lower) * point[k], joint.upper);
  }
}

}  // namespace pmdplan
