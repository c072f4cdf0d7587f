#pragma once
// The baseline of Table 2's "Full" column: hand joints drawn uniformly over their whole joint box,
// every joint at once (the active dimension is always the hand's DOF).
#include <vector>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/planning_space.hpp"

namespace pmdplan {

class FullSpaceHandSampler final : public HandSampler {
 public:
  explicit FullSpaceHandSampler(const PlanningSpace& space);

  int initialDimension() const override { return static_cast<int>(handIndices_.size()); }
  int maxDimension() const override { return static_cast<int>(handIndices_.size()); }
  void sample(int dimension, UnitPoints& points, Configuration& q) const override;
  std::string name() const override { return "full"; }

 private:
  std::vector<int> handIndices_;
  JointLimits handLimits_;
};

}  // namespace pmdplan
