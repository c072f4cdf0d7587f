#include "pmdplan/synergy/hand_fit.hpp"

#include <gtest/gtest.h>

#include "pmdplan/core/input_error.hpp"
#include "support/input_error_matchers.hpp"

namespace pmdplan {
namespace {

SynergyModel twoJointModel() {
  SynergyModel model;
  model.joints = {{"a", 0.0, 1.0}, {"b", -1.0, 1.0}};
  model.mean = Eigen::Vector2d(0.5, 0.5);
  model.directions = Eigen::Vector2d(1.0, 0.0);
  model.sigma = Eigen::VectorXd::Constant(1, 0.1);
  return model;
}

TEST(HandFit, AModelOfExactlyTheHandsJointsFits) {
  EXPECT_NO_THROW(checkSynergyModelFitsHand(twoJointModel(), {"b", "a"}, "m.yaml"));
}

TEST(HandFit, EachMisfitNamesTheFileAndTheField) {
  test::expectInputError([] { checkSynergyModelFitsHand(twoJointModel(), {"a"}, "m.yaml"); }, "m.yaml", "joints",
                         "'b' is not a hand joint of the robot");
  test::expectInputError(
      [] {
        checkSynergyModelFitsHand(twoJointModel(), {"a", "b", "c"}, "m.yaml");
      },
      "m.yaml", "joints", "hand joint 'c' is missing from the synergy model");
  SynergyModel model = twoJointModel();
  model.mean = Eigen::Vector3d(0.5, 0.5, 0.5);
  test::expectInputError(
      [&] {
        checkSynergyModelFitsHand(model, {"a", "b"}, "m.yaml");
      },
      "m.yaml", "mean", "expected one per joint (2)");
  model = twoJointModel();
  model.sigma[0] = -0.1;
  test::expectInputError([&] { checkSynergyModelFitsHand(model, {"a", "b"}, ""); }, "", "sigma", ">= 0");
  model = twoJointModel();
  model.ownAxisJoints = {"a", "a"};
  test::expectInputError(
      [&] {
        checkSynergyModelFitsHand(model, {"a", "b"}, "m.yaml");
      },
      "m.yaml", "own_axis_joints", "listed twice");
}

}  // namespace
}  // namespace pmdplan
