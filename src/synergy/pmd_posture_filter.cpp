#include "pmdplan/synergy/pmd_posture_filter.hpp"

#include <algorithm>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/synergy/synergy_projection.hpp"

namespace pmdplan {

PmdPostureFilter::PmdPostureFilter(SynergyModel model, const JointLimits& handJoints, int directions,
                                   const std::string& modelFile, const std::string& option)
    : model_(std::move(model)), hand_(handJoints), directions_(directions) {
  if (directions < 0 || directions > model_.directionCount())
    throw InputError(modelFile, option,
                     "expected 0 to " + std::to_string(model_.directionCount()) +
                         " PMDs (the model's directions), got " + std::to_string(directions));
  if (static_cast<std::size_t>(model_.jointCount()) != handJoints.size())
    throw InputError(modelFile, "joints",
                     "the model covers " + std::to_string(model_.jointCount()) + " joints, the robot's hand has " +
                         std::to_string(handJoints.size()) + ": a model of another hand?");
  for (const auto& joint : model_.joints) {
    const auto at =
        std::find_if(handJoints.begin(), handJoints.end(), [&](const JointLimit& h) { return h.name == joint.name; });
    if (at == handJoints.end())
      throw InputError(
          modelFile, "joints",
          "the model's joint " + joint.name + " is not a hand joint of the robot: a model of another hand?");
    slot_.push_back(static_cast<int>(at - handJoints.begin()));
    ownAxis_.push_back(std::find(model_.ownAxisJoints.begin(), model_.ownAxisJoints.end(), joint.name) !=
                       model_.ownAxisJoints.end());
  }
}

Eigen::VectorXd PmdPostureFilter::filter(const Eigen::VectorXd& posture) const {
  const int n = model_.jointCount();
  Eigen::VectorXd unit(n);
  for (int j = 0; j < n; ++j)
    unit(j) = model_.joints[static_cast<std::size_t>(j)].normalise(posture(slot_[static_cast<std::size_t>(j)]));
  const Eigen::VectorXd coefficients = synergyCoefficients(model_, unit).head(directions_);
  const Eigen::VectorXd kept = postureFromCoefficients(model_, coefficients);
  Eigen::VectorXd filtered = posture;
  for (int j = 0; j < n; ++j) {
    const auto slot = static_cast<std::size_t>(slot_[static_cast<std::size_t>(j)]);
    const double value = ownAxis_[static_cast<std::size_t>(j)]
                             ? posture(static_cast<Eigen::Index>(slot))
                             : model_.joints[static_cast<std::size_t>(j)].denormalise(kept(j));
    filtered(static_cast<Eigen::Index>(slot)) = std::clamp(value, hand_[slot].lower, hand_[slot].upper);
  }
  return filtered;
}

}  // namespace pmdplan
