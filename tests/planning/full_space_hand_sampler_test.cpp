#include "pmdplan/planning/full_space_hand_sampler.hpp"

#include <gtest/gtest.h>

#include "planning/toy_problem.hpp"

namespace pmdplan {
namespace {

TEST(FullSpaceHandSampler, FillsTheWholeHandBoxAtOnce) {
  const PlanningSpace space = toy::space();
  const FullSpaceHandSampler sampler(space);
  EXPECT_EQ(sampler.initialDimension(), 4);
  EXPECT_EQ(sampler.maxDimension(), 4);
  EXPECT_EQ(sampler.name(), "full");
  UnitPoints random(SampleSequence::Random, 4, {sampler.maxDimension(), 0, 0});
  Eigen::Vector4d low = Eigen::Vector4d::Constant(1.0);
  Eigen::Vector4d high = Eigen::Vector4d::Constant(0.0);
  Eigen::Vector4d sum = Eigen::Vector4d::Zero();
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    Configuration q = toy::start();
    sampler.sample(4, random, q);
    ASSERT_TRUE(space.withinLimits(q, 0.0));
    EXPECT_EQ(q.head(2), toy::start().head(2));
    const Eigen::Vector4d u = space.normalise(q).tail<4>();
    low = low.cwiseMin(u);
    high = high.cwiseMax(u);
    sum += u;
  }
  EXPECT_LT(low.maxCoeff(), 0.001);
  EXPECT_GT(high.minCoeff(), 0.999);
  // Uniform: the mean of each joint is near the middle (standard error about 0.002).
  EXPECT_LT((sum / n - Eigen::Vector4d::Constant(0.5)).cwiseAbs().maxCoeff(), 0.01);
}

}  // namespace
}  // namespace pmdplan
