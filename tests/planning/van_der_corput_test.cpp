#include "pmdplan/planning/van_der_corput.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

namespace pmdplan {
namespace {

TEST(VanDerCorput, VisitsTheEndsThenHalvesTheGaps) {
  const std::vector<double> expected = {0.0, 1.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(vanDerCorput(i, 8), expected[i]) << "index " << i;
}

TEST(VanDerCorput, EveryIntervalEndExactlyOnce) {
  for (const std::size_t intervals : {1u, 2u, 4u, 64u, 1024u}) {
    std::set<std::size_t> seen;
    for (std::size_t i = 0; i <= intervals; ++i) {
      const double scaled = vanDerCorput(i, intervals) * static_cast<double>(intervals);
      ASSERT_EQ(scaled, std::floor(scaled)) << "not a multiple of 1/" << intervals;
      EXPECT_TRUE(seen.insert(static_cast<std::size_t>(scaled)).second) << "repeated at index " << i;
    }
    EXPECT_EQ(seen.size(), intervals + 1);
  }
}

TEST(VanDerCorput, EachPrefixOfPowerOfTwoLengthIsEvenlySpread) {
  // After 2^m + 1 visits the visited points are exactly the multiples of 1/2^m.
  const std::size_t intervals = 256;
  for (std::size_t m = 0; (std::size_t{1} << m) <= intervals; ++m) {
    const std::size_t coarse = std::size_t{1} << m;
    std::set<double> visited;
    for (std::size_t i = 0; i <= coarse; ++i) visited.insert(vanDerCorput(i, intervals));
    for (std::size_t k = 0; k <= coarse; ++k)
      EXPECT_EQ(visited.count(static_cast<double>(k) / static_cast<double>(coarse)), 1u) << "m " << m << " k " << k;
  }
}

TEST(VanDerCorput, RejectsBadArguments) {
  EXPECT_THROW(vanDerCorput(0, 3), std::invalid_argument);
  EXPECT_THROW(vanDerCorput(0, 0), std::invalid_argument);
  EXPECT_THROW(vanDerCorput(9, 8), std::invalid_argument);
}

TEST(SegmentIntervals, IsTheSmallestPowerOfTwoWithSpacingAtMostRho) {
  for (const double length : {0.0, 1e-4, 0.001, 0.3, 0.8, 1.0, 2.449}) {
    for (const double rho : {0.001, 0.002, 0.006, 0.024, 0.12, 0.72, 4.32}) {
      const std::size_t n = segmentIntervals(length, rho);
      EXPECT_EQ(n & (n - 1), 0u) << n << " is not a power of two";
      EXPECT_LE(length / static_cast<double>(n), rho) << "length " << length << " rho " << rho;
      if (n > 1) {
        EXPECT_GT(length / static_cast<double>(n / 2), rho) << "not the smallest";
      }
    }
  }
  EXPECT_EQ(segmentIntervals(0.8, 0.001), 1024u);
  EXPECT_EQ(segmentIntervals(0.5, 0.5), 1u);
  EXPECT_EQ(segmentIntervals(0.0, 0.001), 1u);
}

TEST(SegmentIntervals, RejectsNonPositiveSpacing) {
  EXPECT_THROW(segmentIntervals(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(segmentIntervals(1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(segmentIntervals(std::nan(""), 0.1), std::invalid_argument);
  EXPECT_THROW(segmentIntervals(1.0, 1e-300), std::invalid_argument);
}

}  // namespace
}  // namespace pmdplan
