#pragma once
// Algorithm 1 (SampleArm): arm configurations from the hypercube B^a of half-size rho_a, in
// normalised arm-joint space, centred at a point of the segment from c_ini^a to c_goal^a.
#include <Eigen/Core>
#include <vector>

#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/core/sequences/unit_points.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/planning_space.hpp"

namespace pmdplan {

class ArmSegmentSampler {
 public:
  /// `start` and `goal` are full configurations within the space's limits.
  ArmSegmentSampler(const PlanningSpace& space, const Configuration& start, const Configuration& goal);

  /// Length of the start-goal arm segment in normalised arm-joint space (STEPS' input).
  double segmentLength() const { return segmentLength_; }
  /// Arm joints: the coordinates of one draw.
  int dimension() const { return static_cast<int>(armIndices_.size()); }

  /// Writes into the arm entries of `q` a point drawn uniformly from the hypercube of half-size
  /// `halfSize` around the segment point at `step` (0 = start, 1 = goal), intersected with the
  /// joint limits. Sampling the intersection is the same distribution as drawing from the whole box
  /// and rejecting what lies outside the limits, without the wasted draws once rho_a has grown past
  /// the limits; clamping instead would pile samples up on the limits. The hand entries of `q` are
  /// left as they are. The point comes from the points' arm stream (of the arm's dimension).
  void draw(double step, double halfSize, UnitPoints& points, Configuration& q) const;

  /// Algorithm 1: up to `maxTrials` draws until one is free of arm self-collision
  /// (StateValidator::isArmValid). False if none was; `q` then holds the last draw.
  bool sample(double step, double halfSize, UnitPoints& points, StateValidator& validator, Configuration& q,
              int maxTrials = 1) const;

 private:
  std::vector<int> armIndices_;
  JointLimits armLimits_;
  Eigen::VectorXd startUnit_;  ///< normalised arm entries of c_ini, in armIndices order
  Eigen::VectorXd goalUnit_;
  double segmentLength_ = 0.0;
};

}  // namespace pmdplan
