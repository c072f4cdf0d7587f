#include "pmdplan/synergy/synergy_fit.hpp"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <cmath>
#include <cstddef>
#include <vector>

#include "../../src/synergy/deterministic_random.hpp"
#include "support/input_error_matchers.hpp"

namespace pmdplan {
namespace {

// Five PCA joints with different ranges, one own-axis joint and one constant joint.
JointLimits testJoints() {
  return {{"spin", -1.0, 2.0}, {"a", 0.0, 1.0},  {"b", -0.5, 0.5}, {"fixed", -0.2, 0.2},
          {"c", 0.1, 1.6},     {"d", -3.0, 3.0}, {"e", 0.0, 0.25}};
}
const std::vector<int> kPcaColumns{1, 2, 4, 5, 6};

struct AnalyticCase {
  Eigen::MatrixXd directions;  // 5 x 5, orthonormal, in normalised units of the PCA joints
  Eigen::VectorXd variances;   // decreasing
  Eigen::MatrixXd postures;    // frames x 7, rad
};

// Data with exactly known principal directions: a two-level full factorial design (every sign
// pattern of 5 unit coefficients, repeated) has an exactly diagonal sample covariance.
AnalyticCase analyticCase() {
  AnalyticCase c;
  Eigen::MatrixXd seed(5, 5);
  seed << 0.9, 0.1, -0.3, 0.2, 0.05, 0.2, 0.8, 0.1, -0.4, 0.3, -0.1, 0.3, 0.7, 0.2, -0.2, 0.3, -0.2, 0.1, 0.9, 0.1,
      0.05, 0.2, -0.1, 0.1, 0.95;
  c.directions = Eigen::HouseholderQR<Eigen::MatrixXd>(seed).householderQ() * Eigen::MatrixXd::Identity(5, 5);
  c.variances.resize(5);
  c.variances << 0.02, 0.01, 0.004, 0.0015, 0.0004;
  const JointLimits joints = testJoints();
  const int repeats = 40;
  c.postures.resize(32 * repeats, 7);
  for (int f = 0; f < 32 * repeats; ++f) {
    Eigen::VectorXd z(5);
    for (int k = 0; k < 5; ++k) z(k) = ((f % 32) >> k) & 1 ? 1.0 : -1.0;
    const Eigen::VectorXd unit =
        Eigen::VectorXd::Constant(5, 0.5) + c.directions * (c.variances.cwiseSqrt().asDiagonal() * z);
    for (int k = 0; k < 5; ++k)
      c.postures(f, kPcaColumns[static_cast<std::size_t>(k)]) =
          joints[static_cast<std::size_t>(kPcaColumns[static_cast<std::size_t>(k)])].denormalise(unit(k));
    c.postures(f, 0) = joints[0].denormalise(0.5 + 0.4 * std::sin(0.37 * f));  // the own-axis joint wanders on its own
    c.postures(f, 3) = 0.0;                                                    // fixed
  }
  return c;
}

SynergyFitSettings ownSpin() { return SynergyFitSettings{{"spin"}}; }

TEST(SynergyFit, RecoversKnownDirectionsAndVariances) {
  const AnalyticCase c = analyticCase();
  const SynergyFit fit = fitSynergyModel(c.postures, testJoints(), ownSpin(), {"analytic", "", "analytic case"});
  ASSERT_EQ(fit.model.directionCount(), 5);
  const double frames = static_cast<double>(c.postures.rows());
  for (int k = 0; k < 5; ++k) {
    Eigen::VectorXd recovered(5);
    for (int r = 0; r < 5; ++r) recovered(r) = fit.model.directions(kPcaColumns[static_cast<std::size_t>(r)], k);
    EXPECT_GT(std::abs(recovered.dot(c.directions.col(k))), 0.999) << "direction " << k + 1;
    // The design's sample variance is variance * frames / (frames - 1).
    const double expected = c.variances(k) * frames / (frames - 1);
    EXPECT_NEAR(fit.model.sigma(k) * fit.model.sigma(k), expected, 0.01 * expected) << "direction " << k + 1;
    EXPECT_NEAR(fit.model.varianceFraction(k), c.variances(k) / c.variances.sum(), 1e-9);
  }
  EXPECT_NEAR(fit.cumulativeVariance(1), (0.02 + 0.01) / c.variances.sum(), 1e-9);
  EXPECT_NEAR(fit.cumulativeVariance(4), 1.0, 1e-12);
}

TEST(SynergyFit, DirectionsAreOrthonormalOrderedAndSignFixed) {
  const SynergyFit fit = fitSynergyModel(analyticCase().postures, testJoints(), ownSpin(), {});
  const Eigen::MatrixXd& d = fit.model.directions;
  EXPECT_TRUE((d.transpose() * d).isIdentity(1e-9));
  EXPECT_TRUE(fit.model.orthonormal);
  for (int k = 0; k < d.cols(); ++k) {
    Eigen::Index largest = 0;
    d.col(k).cwiseAbs().maxCoeff(&largest);
    EXPECT_GT(d(largest, k), 0) << "direction " << k + 1;
    if (k > 0) {
      EXPECT_GE(fit.model.sigma(k - 1), fit.model.sigma(k));
    }
  }
}

TEST(SynergyFit, OwnAxisAndConstantJointsStayOutOfThePca) {
  const SynergyFit fit = fitSynergyModel(analyticCase().postures, testJoints(), ownSpin(), {});
  EXPECT_EQ(fit.pcaJoints, (std::vector<std::string>{"a", "b", "c", "d", "e"}));
  EXPECT_EQ(fit.constantJoints, std::vector<std::string>{"fixed"});
  EXPECT_EQ(fit.varyingJoints, (std::vector<std::string>{"spin", "a", "b", "c", "d", "e"}));
  EXPECT_EQ(fit.model.ownAxisJoints, std::vector<std::string>{"spin"});
  EXPECT_TRUE(fit.model.directions.row(0).isZero(0));
  EXPECT_TRUE(fit.model.directions.row(3).isZero(0));
  EXPECT_NEAR(fit.model.mean(3), 0.5, 1e-12);  // 0 rad in [-0.2, 0.2]
  EXPECT_NEAR(fit.model.mean(1), 0.5, 1e-12);
}

TEST(SynergyFit, CorrelationMatrixOverTheMovingJoints) {
  const AnalyticCase c = analyticCase();
  const SynergyFit fit = fitSynergyModel(c.postures, testJoints(), ownSpin(), {});
  ASSERT_EQ(fit.correlation.rows(), 6);
  EXPECT_TRUE(fit.correlation.diagonal().isOnes(1e-12));
  EXPECT_TRUE(fit.correlation.isApprox(fit.correlation.transpose()));
  // Joint "a" against joint "b", straight from the definition.
  const Eigen::VectorXd a = c.postures.col(1).array() - c.postures.col(1).mean();
  const Eigen::VectorXd b = c.postures.col(2).array() - c.postures.col(2).mean();
  EXPECT_NEAR(fit.correlation(1, 2), a.dot(b) / (a.norm() * b.norm()), 1e-12);
}

TEST(SynergyFit, FewerFramesThanJointsIsAnError) {
  const Eigen::MatrixXd postures = analyticCase().postures.topRows(5);  // 5 frames, 5 PCA joints
  test::expectInputError(
      [&] {
        fitSynergyModel(postures, testJoints(), ownSpin(), {"rec.csv", "lines 2-6", ""});
      },
      "rec.csv", "lines 2-6", "5 frames for 5 joints in the PCA; need at least 6");
  EXPECT_NO_THROW(fitSynergyModel(analyticCase().postures.topRows(6), testJoints(), ownSpin(), {}));
}

TEST(SynergyFit, ConstantDataSetIsAnError) {
  Eigen::MatrixXd postures = analyticCase().postures;
  for (const int column : kPcaColumns) postures.col(column).setConstant(postures(0, column));
  test::expectInputError(
      [&] {
        fitSynergyModel(postures, testJoints(), ownSpin(), {"rec.csv", "lines 2-1281", ""});
      },
      "rec.csv", "lines 2-1281", "constant data set");
}

TEST(SynergyFit, PosturesBeyondTheLimitsAreAnError) {
  Eigen::MatrixXd postures = analyticCase().postures;
  postures(10, 6) = 0.3;  // joint e ends at 0.25
  test::expectInputError(
      [&] {
        fitSynergyModel(postures, testJoints(), ownSpin(), {"rec.csv", "lines 2-9", ""});
      },
      "rec.csv", "lines 2-9", "joint e leaves its limits");
}

TEST(SynergyFit, UnknownOwnAxisJointIsAnError) {
  test::expectInputError(
      [] { fitSynergyModel(analyticCase().postures, testJoints(), SynergyFitSettings{{"thumb"}}, {}); }, "", "own-axis",
      "'thumb' is not one of the hand joints");
}

TEST(SynergyFit, ProvenanceGoesIntoTheModel) {
  const SynergyFit fit = fitSynergyModel(analyticCase().postures, testJoints(), ownSpin(), {"f", "l", "from the test"});
  EXPECT_EQ(fit.model.provenance, "from the test");
  EXPECT_EQ(fit.frames, 1280);
}

TEST(SynergyFit, TheResultDoesNotDependOnTheCpuCacheSizes) {
  // Eigen blocks large products by the cache sizes it reads off the CPU; the fit must not.
  Eigen::MatrixXd postures(20000, 7);
  DeterministicRandom random(7);
  const JointLimits joints = testJoints();
  for (Eigen::Index f = 0; f < postures.rows(); ++f) {
    const double shared = random.uniform();
    for (Eigen::Index j = 0; j < 7; ++j) {
      const double t = j == 3 ? 0.5 : 0.5 * shared + 0.5 * random.uniform();
      postures(f, j) = joints[static_cast<std::size_t>(j)].denormalise(t);
    }
  }
  const std::ptrdiff_t l1 = Eigen::l1CacheSize(), l2 = Eigen::l2CacheSize(), l3 = Eigen::l3CacheSize();
  std::vector<SynergyFit> fits;
  for (const std::ptrdiff_t firstLevel : {8 * 1024, 32 * 1024, 64 * 1024}) {
    Eigen::setCpuCacheSizes(firstLevel, 256 * 1024, 4 * 1024 * 1024);
    fits.push_back(fitSynergyModel(postures, joints, ownSpin(), {}));
    EXPECT_EQ(Eigen::l1CacheSize(), firstLevel) << "the fit restores the sizes it found";
  }
  Eigen::setCpuCacheSizes(l1, l2, l3);
  for (std::size_t i = 1; i < fits.size(); ++i) {
    EXPECT_EQ(fits[i].model.directions, fits[0].model.directions);
    EXPECT_EQ(fits[i].cumulativeVariance, fits[0].cumulativeVariance);
    EXPECT_EQ(fits[i].correlation, fits[0].correlation);
  }
}

}  // namespace
}  // namespace pmdplan
