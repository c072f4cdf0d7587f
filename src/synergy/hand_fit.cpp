#include "pmdplan/synergy/hand_fit.hpp"

#include <algorithm>
#include <cmath>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"

namespace pmdplan {

void checkSynergyModelFitsHand(const SynergyModel& model, const std::vector<std::string>& handJoints,
                               const std::string& modelFile) {
  const auto reject = [&](const std::string& field, const std::string& message) {
    throw InputError(modelFile, field, message);
  };
  const int n = model.jointCount();
  if (n == 0) reject("joints", "the synergy model covers no joints");
  std::vector<char> covered(handJoints.size(), 0);
  for (const JointLimit& joint : model.joints) {
    const auto at = std::find(handJoints.begin(), handJoints.end(), joint.name);
    if (at == handJoints.end()) reject("joints", quotedText(joint.name) + " is not a hand joint of the robot");
    if (covered[static_cast<std::size_t>(at - handJoints.begin())]++ != 0)
      reject("joints", quotedText(joint.name) + " is listed twice");
    if (!std::isfinite(joint.lower) || !std::isfinite(joint.upper) || !(joint.range() > 0.0))
      reject("joints", quotedText(joint.name) + " needs finite limits with lower < upper");
  }
  for (std::size_t i = 0; i < handJoints.size(); ++i)
    if (covered[i] == 0)
      reject("joints", "the robot's hand joint " + quotedText(handJoints[i]) + " is missing from the synergy model");

  if (model.mean.size() != n)
    reject("mean",
           "has " + std::to_string(model.mean.size()) + " entries, expected one per joint (" + std::to_string(n) + ")");
  if (!model.mean.allFinite()) reject("mean", "must hold finite numbers");
  if (model.directions.rows() != n)
    reject("directions", "have " + std::to_string(model.directions.rows()) + " rows, expected one per joint (" +
                             std::to_string(n) + ")");
  if (model.directions.cols() < 1) reject("directions", "the model has no principal motion direction");
  if (!model.directions.allFinite()) reject("directions", "must hold finite numbers");
  if (model.sigma.size() != model.directions.cols())
    reject("sigma", "has " + std::to_string(model.sigma.size()) + " entries, expected one per direction (" +
                        std::to_string(model.directions.cols()) + ")");
  if (!model.sigma.allFinite() || (model.sigma.array() < 0.0).any()) reject("sigma", "must hold finite numbers >= 0");

  std::vector<std::string> ownAxes;
  for (const std::string& name : model.ownAxisJoints) {
    if (model.jointIndex(name) < 0) reject("own_axis_joints", quotedText(name) + " is not one of the model's joints");
    if (std::find(ownAxes.begin(), ownAxes.end(), name) != ownAxes.end())
      reject("own_axis_joints", quotedText(name) + " is listed twice");
    ownAxes.push_back(name);
  }
}

}  // namespace pmdplan
