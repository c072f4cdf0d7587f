#include "pmdplan/planning/synergy_hand_sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "planning/toy_problem.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

/// The hand part of a configuration in the model's normalised units.
Eigen::Vector4d handUnit(const PlanningSpace& space, const Configuration& q) { return space.normalise(q).tail<4>(); }

TEST(SynergyHandSampler, DimensionsRunFromThumbPlusOnePmdToTheModelMaximum) {
  const PlanningSpace space = toy::space();
  const SynergyHandSampler sampler(space, toy::synergyModel());
  EXPECT_EQ(sampler.initialDimension(), 2);
  EXPECT_EQ(sampler.maxDimension(), 4);
  const SynergyHandSampler capped(space, toy::synergyModel(), {2.0, 2});
  EXPECT_EQ(capped.maxDimension(), 3);
  EXPECT_EQ(capped.directionCount(), 2);
  EXPECT_EQ(sampler.name(), "pmd");
}

TEST(SynergyHandSampler, EachDimensionUsesOnlyItsFirstAxes) {
  const PlanningSpace space = toy::space();
  const SynergyModel model = toy::synergyModel();
  const SynergyHandSampler sampler(space, model);
  UnitPoints random(SampleSequence::Random, 1, {sampler.maxDimension(), 0, 0});
  for (int dimension = 2; dimension <= 4; ++dimension) {
    const int pmds = dimension - 1;
    double thumbLow = 1.0;
    double thumbHigh = 0.0;
    Eigen::VectorXd coefficientReach = Eigen::VectorXd::Zero(3);
    for (int i = 0; i < 3000; ++i) {
      Configuration q = toy::start();
      sampler.sample(dimension, random, q);
      EXPECT_EQ(q.head(2), toy::start().head(2)) << "the arm is left alone";
      const Eigen::Vector4d u = handUnit(space, q);
      thumbLow = std::min(thumbLow, u[0]);
      thumbHigh = std::max(thumbHigh, u[0]);
      // Coefficients along the orthonormal PMDs (the thumb entry is its own axis).
      Eigen::Vector4d offset = u - model.mean;
      offset[0] = 0.0;
      const Eigen::Vector3d s = model.directions.transpose() * offset;
      for (int k = 0; k < 3; ++k) {
        if (k < pmds) {
          EXPECT_LE(std::abs(s[k]), 2.0 * model.sigma[k] + 1e-9) << "PMD " << k + 1 << " beyond kappa sigma";
          coefficientReach[k] = std::max(coefficientReach[k], std::abs(s[k]));
        } else {
          EXPECT_NEAR(s[k], 0.0, 1e-9) << "PMD " << k + 1 << " is not active at dimension " << dimension;
        }
      }
    }
    EXPECT_LT(thumbLow, 0.01) << "the thumb base spans its whole range";
    EXPECT_GT(thumbHigh, 0.99);
    for (int k = 0; k < pmds; ++k) EXPECT_GT(coefficientReach[k], 1.9 * model.sigma[k]) << "box not filled";
  }
}

TEST(SynergyHandSampler, ClampsToTheJointLimits) {
  const PlanningSpace space = toy::space();
  SynergyModel model = toy::synergyModel();
  model.sigma = Eigen::Vector3d(1.0, 1.0, 1.0);  // kappa sigma = 2: far past the limits
  const SynergyHandSampler sampler(space, model);
  UnitPoints random(SampleSequence::Random, 2, {sampler.maxDimension(), 0, 0});
  int atLimit = 0;
  for (int i = 0; i < 1000; ++i) {
    Configuration q = toy::start();
    sampler.sample(4, random, q);
    ASSERT_TRUE(space.withinLimits(q, 0.0));
    const Eigen::Vector4d u = handUnit(space, q);
    if (u.minCoeff() <= 1e-12 || u.maxCoeff() >= 1.0 - 1e-12) ++atLimit;
  }
  EXPECT_GT(atLimit, 500);
}

TEST(SynergyHandSampler, DimensionsOutsideTheRangeAreClamped) {
  const PlanningSpace space = toy::space();
  const SynergyModel model = toy::synergyModel();
  const SynergyHandSampler sampler(space, model);
  UnitPoints first(SampleSequence::Random, 9, {sampler.maxDimension(), 0, 0});
  UnitPoints second(SampleSequence::Random, 9, {sampler.maxDimension(), 0, 0});
  Configuration a = toy::start();
  Configuration b = toy::start();
  sampler.sample(99, first, a);
  sampler.sample(4, second, b);
  EXPECT_EQ(a, b);
}

TEST(SynergyHandSampler, TheSameSeedGivesTheSameSamples) {
  const PlanningSpace space = toy::space();
  const SynergyHandSampler sampler(space, toy::synergyModel());
  UnitPoints first(SampleSequence::Random, 123, {sampler.maxDimension(), 0, 0});
  UnitPoints second(SampleSequence::Random, 123, {sampler.maxDimension(), 0, 0});
  for (int i = 0; i < 50; ++i) {
    Configuration a = toy::start();
    Configuration b = toy::start();
    sampler.sample(2 + i % 3, first, a);
    sampler.sample(2 + i % 3, second, b);
    ASSERT_EQ(a, b);
  }
}

void expectRejected(const SynergyModel& model, const std::string& field, SynergySamplingSettings parameters = {}) {
  try {
    SynergyHandSampler sampler(toy::space(), model, parameters);
    ADD_FAILURE() << "accepted a bad model (expected an error on " << field << ")";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), field) << error.what();
  }
}

TEST(SynergyHandSampler, RejectsModelsThatDoNotFitTheHand) {
  SynergyModel model = toy::synergyModel();
  model.joints[1].name = "elbow";
  expectRejected(model, "joints");  // an arm joint

  model = toy::synergyModel();
  model.joints.pop_back();
  model.mean = model.mean.head(3).eval();
  model.directions = model.directions.topRows(3).eval();
  expectRejected(model, "joints");  // finger_c missing

  model = toy::synergyModel();
  model.mean = Eigen::VectorXd::Constant(3, 0.5);
  expectRejected(model, "mean");

  model = toy::synergyModel();
  model.directions = Eigen::MatrixXd::Zero(4, 0);
  model.sigma = Eigen::VectorXd(0);
  expectRejected(model, "directions");

  model = toy::synergyModel();
  model.sigma = Eigen::Vector2d(0.1, 0.1);
  expectRejected(model, "sigma");

  model = toy::synergyModel();
  model.sigma[1] = -0.1;
  expectRejected(model, "sigma");

  model = toy::synergyModel();
  model.ownAxisJoints = {"pinkie"};
  expectRejected(model, "own_axis_joints");

  expectRejected(toy::synergyModel(), "kappa", {0.0, 4});
  expectRejected(toy::synergyModel(), "max_directions", {2.0, 0});
}

}  // namespace
}  // namespace pmdplan
