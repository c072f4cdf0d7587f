#include "pmdplan/bench/human_likeness.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pmdplan {
namespace {

// One arm joint and two hand joints over [0, 2]; the model's one PMD runs along hand joint 1
// with sigma 0.1 (normalised), so hand joint 2 is off the subspace.
struct Toy {
  PlanningSpace space;
  SynergyModel model;
  std::vector<int> slots = {1, 2};
  Toy() {
    space.joints = {{"arm", 0.0, 2.0}, {"h1", 0.0, 2.0}, {"h2", 0.0, 2.0}};
    space.armIndices = {0};
    space.handIndices = {1, 2};
    model.joints = {{"h1", 0.0, 2.0}, {"h2", 0.0, 2.0}};
    model.mean = Eigen::Vector2d(0.5, 0.5);
    model.directions = Eigen::MatrixXd(2, 1);
    model.directions << 1.0, 0.0;
    model.sigma = Eigen::VectorXd::Constant(1, 0.1);
    model.varianceFraction = Eigen::VectorXd::Constant(1, 1.0);
  }
  /// Joint values from normalised hand values (arm at 0).
  static Configuration at(double h1, double h2) { return Eigen::Vector3d(0.0, 2.0 * h1, 2.0 * h2); }
};

TEST(HumanLikeness, AStillHandAtTheMeanIsPerfectlyHuman) {
  const Toy toy;
  const auto h = measureHumanLikeness({Toy::at(0.5, 0.5)}, toy.space, toy.model, toy.slots);
  EXPECT_DOUBLE_EQ(h.subspaceDistanceMean, 0.0);
  EXPECT_DOUBLE_EQ(h.subspaceDistanceMax, 0.0);
  EXPECT_DOUBLE_EQ(h.mahalanobisMean, 0.0);
}

TEST(HumanLikeness, MovingAlongThePmdStaysInTheSubspaceWithMahalanobisInSigmas) {
  const Toy toy;
  // Two sigmas out along the PMD, both nodes: distance 0, Mahalanobis 2.
  const auto h = measureHumanLikeness({Toy::at(0.7, 0.5), Toy::at(0.7, 0.5)}, toy.space, toy.model, toy.slots);
  EXPECT_NEAR(h.subspaceDistanceMax, 0.0, 1e-12);
  EXPECT_NEAR(h.mahalanobisMean, 2.0, 1e-12);
}

TEST(HumanLikeness, MeansAreTakenAlongThePathAndTheMaximumAtItsWorstPosture) {
  const Toy toy;
  // The hand leaves the subspace linearly: 0 at the start, 0.5 at the end. Whatever the number of
  // steps, the walk's points are evenly spread, so the mean is 0.25; the maximum is at the end.
  const auto h = measureHumanLikeness({Toy::at(0.5, 0.5), Toy::at(0.5, 1.0)}, toy.space, toy.model, toy.slots);
  EXPECT_NEAR(h.subspaceDistanceMean, 0.25, 1e-12);
  EXPECT_NEAR(h.subspaceDistanceMax, 0.5, 1e-12);
  // Then an arm-only stretch of the same length at the far posture: with steps of 0.125 the walk
  // has 0, 0.125, ..., 0.5 on the first segment and four more points at 0.5 on the second.
  HumanLikenessSettings options;
  options.step = 0.125;
  const auto longer =
      measureHumanLikeness({Toy::at(0.5, 0.5), Toy::at(0.5, 1.0), Configuration(Eigen::Vector3d(1.0, 1.0, 2.0))},
                           toy.space, toy.model, toy.slots, options);
  EXPECT_NEAR(longer.subspaceDistanceMax, 0.5, 1e-12);
  EXPECT_NEAR(longer.subspaceDistanceMean, (0.0 + 0.125 + 0.25 + 0.375 + 0.5 + 4 * 0.5) / 9.0, 1e-12);
}

TEST(HumanLikeness, AnEmptyPathIsAProgrammingError) {
  const Toy toy;
  EXPECT_THROW(measureHumanLikeness({}, toy.space, toy.model, toy.slots), std::invalid_argument);
}

}  // namespace
}  // namespace pmdplan
