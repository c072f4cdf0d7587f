#include "pmdplan/bench/human_likeness_independent.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pmdplan/bench/human_likeness.hpp"
#include "pmdplan/synergy/kautham_sah_synergies.hpp"

namespace pmdplan {
namespace {

// One arm joint, then the SAH's 13 hand joints with the Kautham table's limits; a planner model of
// one PMD (along thumb_abduction) that the independent measures must not look at.
struct SahSpace {
  PlanningSpace space;
  SynergyModel model;
  std::vector<int> slots;
  SahSpace() {
    const KauthamSahSynergies& table = kauthamSahSynergies();
    space.joints.push_back({"arm", -1.0, 1.0});
    space.armIndices = {0};
    for (std::size_t j = 0; j < table.limits.size(); ++j) {
      space.joints.push_back(table.limits[j]);
      space.handIndices.push_back(static_cast<int>(j) + 1);
      slots.push_back(static_cast<int>(j) + 1);
    }
    model.joints = table.limits;
    model.mean = Eigen::VectorXd::Constant(13, 0.5);
    model.directions = Eigen::MatrixXd::Zero(13, 1);
    model.directions(1, 0) = 1.0;
    model.sigma = Eigen::VectorXd::Constant(1, 0.1);
    model.varianceFraction = Eigen::VectorXd::Constant(1, 1.0);
  }
  int slot(const std::string& joint) const { return space.indexOf(joint); }
  /// The configuration whose hand has the table's normalised values `unit` (arm at 0).
  Configuration hand(const Eigen::VectorXd& unit) const {
    Eigen::VectorXd full(14);
    full(0) = 0.5;
    full.tail(13) = unit;
    return space.denormalise(full);
  }
};

TEST(AuthorsSubspaceDistance, ZeroAlongTheAuthorsPmdsAndTheThumbBase) {
  const SahSpace sah;
  const auto reference = independentHandReference(sah.space);
  ASSERT_TRUE(reference);
  const KauthamSahSynergies& table = kauthamSahSynergies();
  Eigen::VectorXd unit = table.mean + 0.3 * table.directions.col(0) - 0.2 * table.directions.col(3);
  unit(0) = 0.9;  // thumb base: its own axis
  EXPECT_NEAR(authorsSubspaceDistance(*reference, sah.hand(table.mean)), 0.0, 1e-12);
  EXPECT_NEAR(authorsSubspaceDistance(*reference, sah.hand(unit)), 0.0, 1e-12);
}

TEST(AuthorsSubspaceDistance, MiddleAbductionIsOffEveryAuthorsPmd) {
  // No PMD of the table moves the middle finger's abduction (the glove does not drive it), so a
  // posture that only moves it by 0.2 normalised units lies exactly 0.2 from the subspace.
  const SahSpace sah;
  const auto reference = independentHandReference(sah.space);
  ASSERT_TRUE(reference);
  Eigen::VectorXd unit = kauthamSahSynergies().mean;
  unit(7) += 0.2;
  EXPECT_NEAR(authorsSubspaceDistance(*reference, sah.hand(unit)), 0.2, 1e-12);
}

TEST(AuthorsSubspaceDistance, NeedsEveryHandJointOfTheTable) {
  SahSpace sah;
  sah.space.joints[13].name = "little_medium";
  EXPECT_FALSE(independentHandReference(sah.space));
}

// From the table's mean, change the normalised values of some joints.
Configuration moved(const SahSpace& sah, const std::vector<std::pair<std::string, double>>& changes) {
  Eigen::VectorXd full = sah.space.normalise(sah.hand(kauthamSahSynergies().mean));
  for (const auto& [joint, change] : changes) full(sah.slot(joint)) += change;
  return sah.space.denormalise(full);
}

TEST(JointCoupling, KnownValuesOfHandMadeMotions) {
  const SahSpace sah;
  const auto reference = independentHandReference(sah.space);
  ASSERT_TRUE(reference);
  const Configuration rest = moved(sah, {});
  // middle_proximal and ring_proximal (Fig. 7: positive, both flexion) move together by d: the pair
  // gives 2d^2 against d^2 + d^2; middle_proximal also sits in the pair with ring_abduction, which
  // stays: 0 against d^2. C = 2d^2 / 3d^2.
  EXPECT_NEAR(
      jointCoupling({rest, moved(sah, {{"middle_proximal", 0.1}, {"ring_proximal", 0.1}})}, sah.space, *reference),
      2.0 / 3.0, 1e-12);
  EXPECT_NEAR(
      jointCoupling({rest, moved(sah, {{"middle_proximal", 0.1}, {"ring_proximal", -0.1}})}, sah.space, *reference),
      -2.0 / 3.0, 1e-12);
  // Fig. 7's middle_proximal & ring_abduction is positive in the paper's signs, where flexion is
  // negative: in ours flexing the middle finger goes with closing the ring abduction. Alone in
  // motion: C = 2 s a b / (a^2 + b^2 + a^2 (with ring_proximal) + b^2 (with index_abduction)).
  const double a = 0.1, b = -0.05;
  EXPECT_NEAR(jointCoupling({rest, moved(sah, {{"middle_proximal", a}, {"ring_abduction", b}})}, sah.space, *reference),
              2.0 * a * -b / (2 * a * a + 2 * b * b), 1e-12);
  // Joints outside the pairs, and the arm, do not count; a still hand scores 0.
  EXPECT_DOUBLE_EQ(jointCoupling({rest, moved(sah, {{"thumb_medium", 0.3}, {"arm", 0.3}})}, sah.space, *reference),
                   0.0);
}

TEST(JointCoupling, IsAnArcLengthIntegralSoSplittingASegmentChangesNothing) {
  const SahSpace sah;
  const auto reference = independentHandReference(sah.space);
  ASSERT_TRUE(reference);
  const Configuration a = moved(sah, {});
  const Configuration b = moved(sah, {{"index_medium", 0.2}, {"middle_medium", 0.1}});
  const Configuration c = moved(sah, {{"index_abduction", 0.1}, {"ring_abduction", 0.1}});
  const Configuration halfway = a + 0.5 * (b - a);
  EXPECT_NEAR(jointCoupling({a, b, c}, sah.space, *reference), jointCoupling({a, halfway, b, c}, sah.space, *reference),
              1e-12);
}

TEST(IndependentHumanLikeness, AMotionAlongTheAuthorsSynergiesBeatsRandomJointMotion) {
  const SahSpace sah;
  const KauthamSahSynergies& table = kauthamSahSynergies();
  // Open and close the hand along PMD 1 and 2 (the two that carry most of the human variance).
  std::vector<Configuration> synergyPath;
  for (const double t : {-0.3, 0.3, -0.1})
    synergyPath.push_back(sah.hand(table.mean + t * table.directions.col(0) + 0.5 * t * table.directions.col(1)));
  const HumanLikeness synergy = measureHumanLikeness(synergyPath, sah.space, sah.model, sah.slots);
  ASSERT_TRUE(synergy.independent);
  EXPECT_NEAR(synergy.independent->authorsSubspaceDistanceMax, 0.0, 1e-9);
  EXPECT_GT(synergy.independent->jointCoupling, 0.6);

  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double couplingSum = 0.0;
  const int paths = 20;
  for (int p = 0; p < paths; ++p) {
    std::vector<Configuration> path;
    for (int node = 0; node < 3; ++node) {
      Eigen::VectorXd hand(13);
      for (int j = 0; j < 13; ++j) hand(j) = unit(random);
      path.push_back(sah.hand(hand));
    }
    const HumanLikeness h = measureHumanLikeness(path, sah.space, sah.model, sah.slots);
    ASSERT_TRUE(h.independent);
    EXPECT_GT(h.independent->authorsSubspaceDistanceMean, 0.2) << "random path " << p;
    couplingSum += h.independent->jointCoupling;
  }
  EXPECT_LT(std::abs(couplingSum / paths), 0.3);
  EXPECT_GT(synergy.independent->jointCoupling - couplingSum / paths, 0.4);
}

TEST(IndependentHumanLikeness, AbsentWithoutTheSahHandJoints) {
  SahSpace sah;
  sah.space.joints[3].name = "other";
  EXPECT_FALSE(
      measureHumanLikeness({sah.hand(kauthamSahSynergies().mean)}, sah.space, sah.model, sah.slots).independent);
}

}  // namespace
}  // namespace pmdplan
