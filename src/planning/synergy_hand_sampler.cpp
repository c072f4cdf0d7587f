#include "pmdplan/planning/synergy_hand_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

[[noreturn]] void reject(const std::string& field, const std::string& message) { throw InputError("", field, message); }

}  // namespace

SynergyHandSampler::SynergyHandSampler(const PlanningSpace& space, const SynergyModel& model,
                                       SynergySamplingParameters parameters) {
  if (!(parameters.kappa > 0.0) || !std::isfinite(parameters.kappa))
    reject("kappa", "must be a positive number of standard deviations, got " + std::to_string(parameters.kappa));
  if (parameters.maxDirections < 1)
    reject("max_directions", "must be at least 1, got " + std::to_string(parameters.maxDirections));

  const int n = model.jointCount();
  if (n == 0) reject("joints", "the synergy model covers no joints");
  std::vector<char> isHand(space.joints.size(), 0);
  for (const int i : space.handIndices) isHand[static_cast<std::size_t>(i)] = 1;
  std::vector<char> covered(space.joints.size(), 0);
  for (const JointLimit& joint : model.joints) {
    const int index = space.indexOf(joint.name);
    if (index < 0 || isHand[static_cast<std::size_t>(index)] == 0)
      reject("joints", "'" + joint.name + "' is not a hand joint of the robot");
    if (covered[static_cast<std::size_t>(index)]++ != 0) reject("joints", "'" + joint.name + "' is listed twice");
    if (!std::isfinite(joint.lower) || !std::isfinite(joint.upper) || !(joint.range() > 0.0))
      reject("joints", "'" + joint.name + "' needs finite limits with lower < upper");
    configIndex_.push_back(index);
    modelLimits_.push_back(joint);
    robotLimits_.push_back(space.joints[static_cast<std::size_t>(index)]);
  }
  for (const int i : space.handIndices)
    if (covered[static_cast<std::size_t>(i)] == 0)
      reject("joints", "the robot's hand joint '" + space.joints[static_cast<std::size_t>(i)].name +
                           "' is missing from the synergy model");

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

  for (const std::string& name : model.ownAxisJoints) {
    const auto at = std::find_if(model.joints.begin(), model.joints.end(),
                                 [&](const JointLimit& joint) { return joint.name == name; });
    if (at == model.joints.end()) reject("own_axis_joints", "'" + name + "' is not one of the model's joints");
    const int slot = static_cast<int>(at - model.joints.begin());
    if (std::find(ownAxisSlots_.begin(), ownAxisSlots_.end(), slot) != ownAxisSlots_.end())
      reject("own_axis_joints", "'" + name + "' is listed twice");
    ownAxisSlots_.push_back(slot);
  }

  const Eigen::Index used = std::min<Eigen::Index>(parameters.maxDirections, model.directions.cols());
  mean_ = model.mean;
  directions_ = model.directions.leftCols(used);
  halfWidths_ = parameters.kappa * model.sigma.head(used);
}

void SynergyHandSampler::sample(int dimension, RandomSource& random, Configuration& q) const {
  dimension = std::clamp(dimension, initialDimension(), maxDimension());
  const int ownAxes = std::min(dimension, ownAxisCount());
  const int pmds = dimension - ownAxes;

  // Draw order is fixed (own axes, then PMD 1, 2, ...) so a seed always means the same sample.
  Eigen::VectorXd ownValues(ownAxes);
  for (int k = 0; k < ownAxes; ++k) ownValues[k] = random.uniform01();
  Eigen::VectorXd coefficients(pmds);
  for (int k = 0; k < pmds; ++k) coefficients[k] = random.uniform(-halfWidths_[k], halfWidths_[k]);

  // b + E'·s summed in a fixed order (not Eigen's vectorised product), so every platform agrees
  // to the last bit.
  Eigen::VectorXd unit = mean_;
  for (int k = 0; k < pmds; ++k)
    for (Eigen::Index j = 0; j < unit.size(); ++j) unit[j] += directions_(j, k) * coefficients[k];
  for (int k = 0; k < ownAxes; ++k) unit[ownAxisSlots_[static_cast<std::size_t>(k)]] = ownValues[k];

  for (std::size_t slot = 0; slot < configIndex_.size(); ++slot) {
    const double value = modelLimits_[slot].denormalise(std::clamp(unit[static_cast<Eigen::Index>(slot)], 0.0, 1.0));
    q[configIndex_[slot]] = std::clamp(value, robotLimits_[slot].lower, robotLimits_[slot].upper);
  }
}

}  // namespace pmdplan
