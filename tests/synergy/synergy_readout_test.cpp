#include "pmdplan/synergy/synergy_readout.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/synergy/synergy_projection.hpp"

namespace pmdplan {
namespace {

class SynergyReadoutTest : public ::testing::Test {
 protected:
  RobotModel robot_ = RobotModel::loadBuiltIn("sah_tx90");
  SynergyModel model_ = loadSynergyModel(defaultSynergyModelPath("sah_tx90"));
  std::vector<int> slots_ = modelJointSlots(model_, robot_, "model.yaml");

  /// A configuration whose hand is the normalised posture `unit` (arm at zero).
  Configuration withHand(const Eigen::VectorXd& unit) const {
    Configuration q = Configuration::Zero(robot_.dof());
    for (int j = 0; j < model_.jointCount(); ++j)
      q[slots_[static_cast<std::size_t>(j)]] = model_.joints[static_cast<std::size_t>(j)].denormalise(unit[j]);
    return q;
  }
};

TEST_F(SynergyReadoutTest, APostureBuiltFromTwoPmdsIsOnTheSubspaceOfTwoAndNotOfOne) {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(2);
  s << 0.2, -0.1;
  Eigen::VectorXd unit = postureFromCoefficients(model_, s);
  const int thumbBase = model_.jointIndex("thumb_base");
  unit[thumbBase] = 0.25;  // an own axis is free: it never counts as distance
  const SynergyReadout readout = synergyReadout(model_, slots_, withHand(unit));
  ASSERT_EQ(readout.ownAxis.size(), 1);
  EXPECT_NEAR(readout.ownAxis[0], 0.25, 1e-12);
  EXPECT_NEAR(readout.coefficients[0], 0.2, 1e-12);
  EXPECT_NEAR(readout.coefficients[1], -0.1, 1e-12);
  for (int k = 2; k < model_.directionCount(); ++k) EXPECT_NEAR(readout.coefficients[k], 0.0, 1e-12);
  ASSERT_EQ(readout.distanceFromSubspace.size(), model_.directionCount() + 1);
  EXPECT_NEAR(readout.distanceFromSubspace[0], std::hypot(0.2, 0.1), 1e-12);  // orthonormal directions
  EXPECT_NEAR(readout.distanceFromSubspace[1], 0.1, 1e-12);
  for (int k = 2; k <= model_.directionCount(); ++k) EXPECT_NEAR(readout.distanceFromSubspace[k], 0.0, 1e-12);
}

TEST_F(SynergyReadoutTest, TheDistanceNeverGrowsWithMoreDirections) {
  const Configuration q = robot_.denormalise(Configuration::Constant(robot_.dof(), 0.8));
  const SynergyReadout readout = synergyReadout(model_, slots_, q);
  for (int k = 1; k <= model_.directionCount(); ++k)
    EXPECT_LE(readout.distanceFromSubspace[k], readout.distanceFromSubspace[k - 1] + 1e-12) << k;
  // middle_abduction never moved in the data (no direction has a component on it): 0.8 - 0.5 stays.
  EXPECT_NEAR(readout.distanceFromSubspace[model_.directionCount()], 0.3, 1e-9);
}

TEST_F(SynergyReadoutTest, ANonOrthonormalBasisIsSolvedByLeastSquares) {
  SynergyModel skewed = model_;
  skewed.orthonormal = false;
  skewed.directions.col(1) = (model_.directions.col(0) + model_.directions.col(1)).normalized();
  Eigen::VectorXd s(2);
  s << 0.1, 0.3;
  const SynergyReadout readout = synergyReadout(skewed, slots_, withHand(postureFromCoefficients(skewed, s)));
  EXPECT_NEAR(readout.coefficients[0], 0.1, 1e-9);
  EXPECT_NEAR(readout.coefficients[1], 0.3, 1e-9);
  EXPECT_NEAR(readout.distanceFromSubspace[2], 0.0, 1e-9);
  EXPECT_GT(readout.distanceFromSubspace[1], 0.01);
}

TEST_F(SynergyReadoutTest, AModelForAnotherHandIsAnInputErrorNamingItsFile) {
  SynergyModel other = model_;
  other.joints[3].name = "pinky_medium";
  try {
    modelJointSlots(other, robot_, "other.yaml");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "other.yaml");
    EXPECT_EQ(error.field(), "joints");
    EXPECT_NE(error.message().find("pinky_medium"), std::string::npos);
  }
}

}  // namespace
}  // namespace pmdplan
