#include "pmdplan/synergy/synergy_projection.hpp"

#include <gtest/gtest.h>

namespace pmdplan {
namespace {

SynergyModel twoDirections(bool orthogonal) {
  SynergyModel model;
  model.joints = {{"a", 0, 1}, {"b", 0, 1}, {"c", 0, 1}};
  model.mean = Eigen::Vector3d(0.5, 0.4, 0.6);
  model.directions.resize(3, 2);
  model.directions.col(0) = Eigen::Vector3d(1, 0, 0);
  model.directions.col(1) = orthogonal ? Eigen::Vector3d(0, 0.6, 0.8) : Eigen::Vector3d(0.6, 0.8, 0).normalized();
  model.orthonormal = orthogonal;
  model.sigma = Eigen::Vector2d(0.2, 0.1);
  model.varianceFraction = Eigen::Vector2d(0.8, 0.2);
  return model;
}

TEST(SynergyProjection, OrthonormalModelProjectsWithTheTranspose) {
  const SynergyModel model = twoDirections(true);
  const Eigen::Vector3d posture(0.7, 0.1, 0.2);
  EXPECT_TRUE(synergyCoefficients(model, posture).isApprox(model.directions.transpose() * (posture - model.mean)));
}

TEST(SynergyProjection, NonOrthogonalBasisRecoversCoefficientsByLeastSquares) {
  const SynergyModel model = twoDirections(false);
  const Eigen::Vector2d coefficients(0.13, -0.21);
  const Eigen::VectorXd posture = postureFromCoefficients(model, coefficients);
  EXPECT_TRUE(synergyCoefficients(model, posture).isApprox(coefficients, 1e-12));
  // The transpose would get it wrong for this basis.
  EXPECT_FALSE((model.directions.transpose() * (posture - model.mean)).isApprox(coefficients, 1e-3));
}

TEST(SynergyProjection, FewerCoefficientsUseTheFirstDirections) {
  const SynergyModel model = twoDirections(true);
  Eigen::VectorXd one(1);
  one << 0.2;
  EXPECT_TRUE(postureFromCoefficients(model, one).isApprox(Eigen::Vector3d(0.7, 0.4, 0.6)));
  EXPECT_THROW(postureFromCoefficients(model, Eigen::VectorXd::Zero(3)), std::invalid_argument);
}

}  // namespace
}  // namespace pmdplan
