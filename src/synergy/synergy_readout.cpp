#include "pmdplan/synergy/synergy_readout.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <stdexcept>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/synergy/synergy_projection.hpp"

namespace pmdplan {

std::vector<int> modelJointSlots(const SynergyModel& model, const RobotModel& robot, const std::string& modelFile) {
  std::vector<int> slots;
  for (const JointLimit& joint : model.joints) {
    const int slot = robot.activeIndex(joint.name);
    if (slot < 0)
      throw InputError(modelFile, "joints",
                       "joint " + quotedText(joint.name) + " is not an active joint of robot '" + robot.name() +
                           "' (is the synergy model for another hand?)");
    slots.push_back(slot);
  }
  return slots;
}

SynergyReadout synergyReadout(const SynergyModel& model, const std::vector<int>& slots,
                              const Configuration& configuration) {
  if (slots.size() != model.joints.size())
    throw std::invalid_argument("synergyReadout: one slot per model joint expected");
  const int n = model.jointCount();
  Eigen::VectorXd posture(n);
  for (int j = 0; j < n; ++j)
    posture[j] = model.joints[static_cast<std::size_t>(j)].normalise(configuration[slots[static_cast<std::size_t>(j)]]);

  SynergyReadout readout;
  readout.ownAxis.resize(static_cast<Eigen::Index>(model.ownAxisJoints.size()));
  // The own axes are free coordinates of the subspace: their deviation never counts as distance.
  Eigen::VectorXd deviation = posture - model.mean;
  for (std::size_t a = 0; a < model.ownAxisJoints.size(); ++a) {
    const int j = model.jointIndex(model.ownAxisJoints[a]);
    if (j < 0)
      throw std::invalid_argument("synergyReadout: own-axis joint '" + model.ownAxisJoints[a] + "' not in the model");
    readout.ownAxis[static_cast<Eigen::Index>(a)] = posture[j];
    deviation[j] = 0.0;
  }
  readout.coefficients = synergyCoefficients(model, posture);

  const int directions = model.directionCount();
  readout.distanceFromSubspace.resize(directions + 1);
  for (int k = 0; k <= directions; ++k) {
    Eigen::VectorXd residual = deviation;
    if (k > 0) {
      const auto basis = model.directions.leftCols(k);
      // Orthonormal columns project with their transpose; any other basis by least squares.
      const Eigen::VectorXd s = model.orthonormal ? Eigen::VectorXd(basis.transpose() * deviation)
                                                  : Eigen::VectorXd(basis.colPivHouseholderQr().solve(deviation));
      residual -= basis * s;
    }
    readout.distanceFromSubspace[k] = residual.norm();
  }
  return readout;
}

}  // namespace pmdplan
