#include "pmdplan/synergy/synergy_projection.hpp"

#include <Eigen/QR>
#include <stdexcept>

namespace pmdplan {

Eigen::VectorXd synergyCoefficients(const SynergyModel& model, const Eigen::VectorXd& normalisedPosture) {
  if (normalisedPosture.size() != model.jointCount())
    throw std::invalid_argument("synergyCoefficients: posture size differs from the model's joint count");
  const Eigen::VectorXd deviation = normalisedPosture - model.mean;
  if (model.orthonormal) return model.directions.transpose() * deviation;
  return model.directions.colPivHouseholderQr().solve(deviation);
}

Eigen::VectorXd postureFromCoefficients(const SynergyModel& model, const Eigen::VectorXd& coefficients) {
  if (coefficients.size() > model.directionCount())
    throw std::invalid_argument("postureFromCoefficients: more coefficients than directions");
  return model.mean + model.directions.leftCols(coefficients.size()) * coefficients;
}

}  // namespace pmdplan
