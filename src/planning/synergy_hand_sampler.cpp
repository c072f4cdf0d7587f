#include "pmdplan/planning/synergy_hand_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/synergy/hand_fit.hpp"

namespace pmdplan {
namespace {

[[noreturn]] void reject(const std::string& field, const std::string& message) { throw InputError("", field, message); }

}  // namespace

SynergyHandSampler::SynergyHandSampler(const PlanningSpace& space, const SynergyModel& model,
                                       SynergySamplingSettings parameters) {
  if (!(parameters.kappa > 0.0) || !std::isfinite(parameters.kappa))
    reject("kappa", "must be a positive number of standard deviations, got " + std::to_string(parameters.kappa));
  if (parameters.maxPmds < 1) reject("max_directions", "must be at least 1, got " + std::to_string(parameters.maxPmds));

  std::vector<std::string> handJoints;
  for (const int i : space.handIndices) handJoints.push_back(space.joints[static_cast<std::size_t>(i)].name);
  checkSynergyModelFitsHand(model, handJoints, "");
  for (const JointLimit& joint : model.joints) {
    const int index = space.indexOf(joint.name);
    configIndex_.push_back(index);
    modelLimits_.push_back(joint);
    robotLimits_.push_back(space.joints[static_cast<std::size_t>(index)]);
  }
  for (const std::string& name : model.ownAxisJoints) ownAxisSlots_.push_back(model.jointIndex(name));

  const Eigen::Index used = std::min<Eigen::Index>(parameters.maxPmds, model.directions.cols());
  mean_ = model.mean;
  directions_ = model.directions.leftCols(used);
  halfWidths_ = parameters.kappa * model.sigma.head(used);
}

void SynergyHandSampler::sample(int dimension, UnitPoints& points, Configuration& q) const {
  dimension = std::clamp(dimension, initialDimension(), maxDimension());
  const int ownAxes = std::min(dimension, ownAxisCount());
  const int pmds = dimension - ownAxes;

  // The point's coordinates in a fixed order (own axes, then PMD 1, 2, ...), so a seed always
  // means the same sample.
  Eigen::VectorXd point(dimension);
  points.next(PointStream::Hand, dimension, point.data());
  const Eigen::VectorXd ownValues = point.head(ownAxes);
  Eigen::VectorXd coefficients(pmds);
  for (int k = 0; k < pmds; ++k) coefficients[k] = -halfWidths_[k] + 2.0 * halfWidths_[k] * point[ownAxes + k];

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
