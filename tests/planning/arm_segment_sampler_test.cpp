#include "pmdplan/planning/arm_segment_sampler.hpp"

#include <gtest/gtest.h>

#include "planning/toy_problem.hpp"

namespace pmdplan {
namespace {

TEST(ArmSegmentSampler, SegmentLengthIsInNormalisedArmSpace) {
  const PlanningSpace space = toy::space();
  const ArmSegmentSampler sampler(space, toy::start(), toy::goal());
  EXPECT_NEAR(sampler.segmentLength(), 0.8, 1e-12) << "only the arm counts, in [0, 1] units";
}

TEST(ArmSegmentSampler, SamplesTheBoxAroundTheSegmentPoint) {
  const PlanningSpace space = toy::space();
  const ArmSegmentSampler sampler(space, toy::start(), toy::goal());
  UnitPoints random(SampleSequence::Random, 3, {0, sampler.dimension(), 0});
  const double rho = 0.01;
  for (const double step : {0.0, 0.25, 0.5, 1.0}) {
    Eigen::Vector2d low = Eigen::Vector2d::Constant(1.0);
    Eigen::Vector2d high = Eigen::Vector2d::Constant(0.0);
    for (int i = 0; i < 2000; ++i) {
      Configuration q = toy::start();
      sampler.draw(step, rho, random, q);
      const Eigen::VectorXd u = space.normalise(q);
      const Eigen::Vector2d arm(u[0], u[1]);
      low = low.cwiseMin(arm);
      high = high.cwiseMax(arm);
      EXPECT_EQ(q.tail(4), toy::start().tail(4)) << "the hand is left alone";
    }
    const Eigen::Vector2d centre(0.1 + 0.8 * step, 0.5);
    EXPECT_GE(low.minCoeff() - (centre.array() - rho).minCoeff(), -1e-12);
    EXPECT_LE((high - (centre.array() + rho).matrix()).maxCoeff(), 1e-12);
    // ... and fills it: the extremes come close to the box faces.
    EXPECT_LT((low - (centre.array() - rho).matrix()).maxCoeff(), 0.001);
    EXPECT_LT(((centre.array() + rho).matrix() - high).maxCoeff(), 0.001);
  }
}

TEST(ArmSegmentSampler, ABoxPastTheLimitsIsCutToThem) {
  PlanningSpace space = toy::space();
  const Configuration start = toy::fromUnit({0.0, 0.98, 0.3, 0.8, 0.8, 0.5});
  const Configuration goal = toy::fromUnit({0.2, 0.98, 0.3, 0.9, 0.7, 0.5});
  const ArmSegmentSampler sampler(space, start, goal);
  UnitPoints random(SampleSequence::Random, 5, {0, sampler.dimension(), 0});
  double lowest = 1.0;
  double highest = 0.0;
  for (int i = 0; i < 4000; ++i) {
    Configuration q = start;
    sampler.draw(0.0, 0.05, random, q);
    EXPECT_TRUE(space.withinLimits(q, 0.0));
    const Eigen::VectorXd u = space.normalise(q);
    lowest = std::min(lowest, u[0]);
    highest = std::max(highest, u[1]);
  }
  EXPECT_LT(lowest, 0.001) << "reaches the lower limit";
  EXPECT_GT(highest, 0.999) << "reaches the upper limit";
  // Uniform over the cut box, not piled up on the limit: no two draws on exactly the limit.
  UnitPoints again(SampleSequence::Random, 5, {0, sampler.dimension(), 0});
  int onLimit = 0;
  for (int i = 0; i < 4000; ++i) {
    Configuration q = start;
    sampler.draw(0.0, 0.05, again, q);
    if (q[0] == space.joints[0].lower) ++onLimit;
  }
  EXPECT_LE(onLimit, 1);
}

TEST(ArmSegmentSampler, Algorithm1RetriesUntilTheArmIsFree) {
  const PlanningSpace space = toy::space();
  // Centre at elbow 0.95 (the edge of the toy's arm self-collision), box 0.05: about half the
  // draws collide.
  const Configuration start = toy::fromUnit({0.1, 0.95, 0.3, 0.8, 0.8, 0.5});
  const Configuration goal = toy::fromUnit({0.9, 0.95, 0.3, 0.9, 0.7, 0.5});
  const ArmSegmentSampler sampler(space, start, goal);
  toy::WallStateValidator validator;
  UnitPoints random(SampleSequence::Random, 11, {0, sampler.dimension(), 0});
  int found = 0;
  for (int i = 0; i < 200; ++i) {
    Configuration q = start;
    if (sampler.sample(0.5, 0.05, random, validator, q, 10)) {
      ++found;
      EXPECT_TRUE(validator.isArmValid(q));
    }
  }
  EXPECT_GT(found, 195);
  int foundWithOneTrial = 0;
  for (int i = 0; i < 200; ++i) {
    Configuration q = start;
    if (sampler.sample(0.5, 0.05, random, validator, q, 1)) ++foundWithOneTrial;
  }
  EXPECT_GT(foundWithOneTrial, 60);
  EXPECT_LT(foundWithOneTrial, 140);
}

}  // namespace
}  // namespace pmdplan
