// The synthetic operator's private random source: same seed, same numbers; sane distributions.
#include "../../src/synergy/deterministic_random.hpp"

#include <gtest/gtest.h>

namespace pmdplan {
namespace {

TEST(DeterministicRandom, SameSeedSameSequence) {
  DeterministicRandom a(42), b(42), c(43);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const double x = a.normal();
    EXPECT_EQ(x, b.normal());
    differs = differs || x != c.normal();
  }
  EXPECT_TRUE(differs);
}

TEST(DeterministicRandom, UniformAndNormalMoments) {
  DeterministicRandom random(7);
  const int n = 200000;
  double sum = 0, sumSquares = 0, uniformSum = 0;
  for (int i = 0; i < n; ++i) {
    const double u = random.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    uniformSum += u;
    const double x = random.normal();
    sum += x;
    sumSquares += x * x;
  }
  EXPECT_NEAR(uniformSum / n, 0.5, 0.005);
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(sumSquares / n, 1.0, 0.01);
  for (int i = 0; i < 1000; ++i) {
    const int k = random.below(4);
    ASSERT_GE(k, 0);
    ASSERT_LT(k, 4);
  }
}

}  // namespace
}  // namespace pmdplan
