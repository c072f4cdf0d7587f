#pragma once
// The paper's filtering of glove postures: a mapped hand posture replaced by its nearest posture
// in the subspace the planner samples — the own-axis joints as they are (SAH: thumb_base) plus the
// mean and the first K principal motion directions — then clamped to the hand's joint limits. Joint values are
// normalised by the model's own limits.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

class PmdPostureFilter {
 public:
  /// `handJoints` is the order of the postures to filter; every model joint must be one of them
  /// and every hand joint a model joint. Throws InputError naming `modelFile` ("joints") when they
  /// differ, and naming field `option` when K is not 0 to the model's direction count.
  PmdPostureFilter(SynergyModel model, const JointLimits& handJoints, int directions, const std::string& modelFile,
                   const std::string& option);

  /// The filtered posture (rad, within the limits), same order as `handJoints`.
  Eigen::VectorXd filter(const Eigen::VectorXd& posture) const;
  int directions() const { return directions_; }

 private:
  SynergyModel model_;
  JointLimits hand_;
  std::vector<int> slot_;      ///< for each model joint, its index among the hand joints
  std::vector<bool> ownAxis_;  ///< per model joint
  int directions_ = 0;
};

}  // namespace pmdplan
