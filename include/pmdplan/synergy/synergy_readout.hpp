#pragma once
// Where a hand posture sits with respect to a synergy model, as the viewer reports it: the
// own-axis values (thumb base), the coefficients along the PMDs, and how far the posture is from
// the subspace the planner samples (own axes plus the first k PMDs) for every k.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

struct SynergyReadout {
  /// Normalised values of the model's own-axis joints, in the order the model lists them.
  Eigen::VectorXd ownAxis;
  /// Coefficients along every direction: D^T (p - b), or least squares for a non-orthonormal basis.
  Eigen::VectorXd coefficients;
  /// Entry k (0 ... direction count): Euclidean distance, in normalised joint units, from the
  /// posture to the nearest posture b + (own axes free) + a combination of the first k directions.
  Eigen::VectorXd distanceFromSubspace;
};

/// For each joint of the model, its index in `robot`'s configurations. Throws InputError naming
/// `modelFile` and "joints" for a model joint the robot has no active joint of that name for.
std::vector<int> modelJointSlots(const SynergyModel& model, const RobotModel& robot, const std::string& modelFile);

/// The readout of the hand posture inside `configuration`; `slots` from modelJointSlots(). Joint
/// values are normalised by the model's limits (the model's own units).
SynergyReadout synergyReadout(const SynergyModel& model, const std::vector<int>& slots,
                              const Configuration& configuration);

}  // namespace pmdplan
