#include "pmdplan/synergy/pmd_posture_filter.hpp"

#include <gtest/gtest.h>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

/// Three joints: `own` an axis of its own, `a` and `b` spanned by PMD 1 (a + b) and PMD 2 (a - b).
SynergyModel model() {
  SynergyModel m;
  m.joints = {{"own", 0, 2}, {"a", -1, 1}, {"b", 0, 1}};
  m.ownAxisJoints = {"own"};
  m.mean = Eigen::Vector3d(0.5, 0.5, 0.5);
  m.directions.resize(3, 2);
  m.directions.col(0) = Eigen::Vector3d(0, 1, 1).normalized();
  m.directions.col(1) = Eigen::Vector3d(0, 1, -1).normalized();
  m.sigma = Eigen::Vector2d(0.2, 0.05);
  m.varianceFraction = Eigen::Vector2d(0.9, 0.1);
  return m;
}

// The hand lists the joints in another order than the model.
const JointLimits kHand{{"b", 0, 1}, {"own", 0, 2}, {"a", -1, 1}};

TEST(PmdPostureFilter, KeepsTheOwnAxisAndTheFirstPmdsComponent) {
  const PmdPostureFilter filter(model(), kHand, 1, "m.yaml", "--project-pmds");
  // Normalised a = 0.75, b = 0.55: deviation (0.25, 0.05) -> along PMD 1: 0.15 each.
  const Eigen::Vector3d posture(0.55, 1.3, 0.5);  // b, own, a (a = 0.5 is 0.75 normalised)
  const Eigen::VectorXd filtered = filter.filter(posture);
  EXPECT_DOUBLE_EQ(filtered(1), 1.3);             // own axis untouched
  EXPECT_NEAR(filtered(0), 0.65, 1e-12);          // b: 0.5 + 0.15
  EXPECT_NEAR(filtered(2), 2 * 0.65 - 1, 1e-12);  // a: normalised 0.65
}

TEST(PmdPostureFilter, AllDirectionsGiveThePostureBackAndNoneTheMean) {
  const Eigen::Vector3d posture(0.55, 1.3, 0.5);
  EXPECT_TRUE(PmdPostureFilter(model(), kHand, 2, "m.yaml", "--project-pmds").filter(posture).isApprox(posture, 1e-12));
  const Eigen::VectorXd mean = PmdPostureFilter(model(), kHand, 0, "m.yaml", "--project-pmds").filter(posture);
  EXPECT_NEAR(mean(0), 0.5, 1e-12);
  EXPECT_NEAR(mean(2), 0.0, 1e-12);
}

TEST(PmdPostureFilter, ClampsToTheHandsLimits) {
  SynergyModel tilted = model();
  tilted.directions.col(0) = Eigen::Vector3d(0, 1, 0.5).normalized();
  const PmdPostureFilter filter(tilted, kHand, 1, "m.yaml", "--project-pmds");
  // a = b = 1 (normalised deviation 0.5 each) lands at a = 1.1, b = 0.8 normalised: a is clamped.
  const Eigen::VectorXd filtered = filter.filter(Eigen::Vector3d(1.0, 0.0, 1.0));
  EXPECT_DOUBLE_EQ(filtered(2), 1.0);
  EXPECT_NEAR(filtered(0), 0.8, 1e-12);
}

TEST(PmdPostureFilter, TooManyDirectionsOrAnotherHandAreInputErrors) {
  EXPECT_THROW(PmdPostureFilter(model(), kHand, 3, "m.yaml", "--project-pmds"), InputError);
  EXPECT_THROW(PmdPostureFilter(model(), kHand, -1, "m.yaml", "--project-pmds"), InputError);
  const JointLimits other{{"b", 0, 1}, {"own", 0, 2}, {"c", -1, 1}};
  try {
    PmdPostureFilter(model(), other, 1, "m.yaml", "--project-pmds");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "m.yaml");
    EXPECT_EQ(error.field(), "joints");
  }
}

}  // namespace
}  // namespace pmdplan
