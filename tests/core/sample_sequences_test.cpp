// The samplers' sequences: Halton's radical inverses and prefix property, the SDK order (each
// level's cells once per block, opposite sub-cells first), and UnitPoints' random streams, which
// must read the one RandomSource exactly as the samplers did before the sequences existed.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "pmdplan/core/sequences/halton_sequence.hpp"
#include "pmdplan/core/sequences/sdk_sequence.hpp"
#include "pmdplan/core/sequences/unit_points.hpp"

namespace pmdplan {
namespace {

/// Points per cell of a grid x grid cover of [0, 1)^2 by the first `count` points of `draw`.
template <typename Draw>
std::vector<int> gridCounts(int grid, int count, Draw draw) {
  std::vector<int> counts(static_cast<std::size_t>(grid * grid), 0);
  for (int i = 0; i < count; ++i) {
    double p[2];
    draw(p);
    EXPECT_TRUE(p[0] >= 0.0 && p[0] < 1.0 && p[1] >= 0.0 && p[1] < 1.0) << "point " << i;
    if (!(p[0] >= 0.0 && p[0] < 1.0 && p[1] >= 0.0 && p[1] < 1.0)) continue;
    ++counts[static_cast<std::size_t>(static_cast<int>(p[0] * grid) * grid + static_cast<int>(p[1] * grid))];
  }
  return counts;
}

TEST(SampleSequence, NamesReadBack) {
  for (const SampleSequence s : {SampleSequence::Random, SampleSequence::Halton, SampleSequence::Sdk})
    EXPECT_EQ(parseSampleSequence(sampleSequenceName(s)), s);
  EXPECT_FALSE(parseSampleSequence("Halton"));
  EXPECT_FALSE(parseSampleSequence(""));
}

TEST(HaltonSequence, RadicalInversesAndPrimes) {
  EXPECT_EQ(firstPrimes(8), (std::vector<unsigned>{2, 3, 5, 7, 11, 13, 17, 19}));
  EXPECT_DOUBLE_EQ(radicalInverseInBase(1, 2), 0.5);
  EXPECT_DOUBLE_EQ(radicalInverseInBase(6, 2), 0.375);      // 110 -> 0.011
  EXPECT_DOUBLE_EQ(radicalInverseInBase(5, 3), 7.0 / 9.0);  // 12 -> 0.21
  EXPECT_DOUBLE_EQ(radicalInverseInBase(0, 7), 0.0);
}

TEST(HaltonSequence, FillsTheSquareFarMoreEvenlyThanRandomNumbers) {
  RandomSource random(3);
  HaltonSequence halton(0, 2, random);
  const std::vector<int> haltonCounts = gridCounts(16, 4096, [&](double* p) { halton.next(2, p); });
  RandomSource uniform(3);
  const std::vector<int> randomCounts = gridCounts(16, 4096, [&](double* p) {
    p[0] = uniform.uniform01();
    p[1] = uniform.uniform01();
  });
  const auto [hMin, hMax] = std::minmax_element(haltonCounts.begin(), haltonCounts.end());
  const auto [rMin, rMax] = std::minmax_element(randomCounts.begin(), randomCounts.end());
  // 16 points per cell on average; Halton stays within a few, random numbers spread by about ±4 σ.
  EXPECT_GE(*hMin, 12);
  EXPECT_LE(*hMax, 20);
  EXPECT_GT(*rMax - *rMin, *hMax - *hMin);
}

TEST(HaltonSequence, TheFirstCoordinatesAreTheLowerDimensionalSequenceAndSeedsShiftIt) {
  RandomSource a(5), b(5), c(6);
  HaltonSequence wide(0, 4, a), narrow(0, 2, b), other(0, 4, c);
  for (int i = 0; i < 50; ++i) {
    double p[4], q[2], r[4];
    wide.next(4, p);
    narrow.next(2, q);
    other.next(4, r);
    EXPECT_EQ(p[0], q[0]);
    EXPECT_EQ(p[1], q[1]);
    EXPECT_NE(p[0], r[0]) << "another seed, another offset";
  }
  double too[5];
  EXPECT_THROW(wide.next(5, too), std::invalid_argument);
}

TEST(SdkSequence, MatricesAreLowerTriangularWithAUnitDiagonal) {
  EXPECT_EQ(sdkMatrix(2), (std::vector<std::uint64_t>{0b01, 0b11}));
  EXPECT_EQ(sdkMatrix(3), (std::vector<std::uint64_t>{0b001, 0b010, 0b111}));
  for (int d = 1; d <= 24; ++d) {
    const std::vector<std::uint64_t> t = sdkMatrix(d);
    ASSERT_EQ(t.size(), static_cast<std::size_t>(d));
    for (int i = 0; i < d; ++i) {
      EXPECT_EQ((t[static_cast<std::size_t>(i)] >> i) & 1U, 1U) << "d " << d << " row " << i;
      EXPECT_EQ(t[static_cast<std::size_t>(i)] >> (i + 1), 0U) << "d " << d << " row " << i;
    }
  }
  EXPECT_THROW(sdkMatrix(0), std::invalid_argument);
}

TEST(SdkSequence, OppositeSubCellsComeFirst) {
  const std::vector<std::vector<std::uint64_t>> level1 = {{0, 0}, {1, 1}, {0, 1}, {1, 0}};
  for (std::uint64_t n = 0; n < 4; ++n) EXPECT_EQ(sdkCell(n, 2, 1), level1[n]) << "sample " << n;
}

TEST(SdkSequence, EveryBlockOfTwoToTheDLSamplesVisitsEachLevelLCellOnce) {
  for (const int d : {1, 2, 3, 5, 6}) {
    const int levels = d <= 3 ? 3 : 2;
    for (int level = 1; level <= levels; ++level) {
      const std::uint64_t block = std::uint64_t{1} << (d * level);
      for (const std::uint64_t start : {std::uint64_t{0}, 3 * block}) {
        std::set<std::vector<std::uint64_t>> seen;
        for (std::uint64_t n = start; n < start + block; ++n) {
          std::vector<std::uint64_t> cell = sdkCell(n, d, levels);
          for (auto& c : cell) c >>= levels - level;  // the level-`level` cell holding it
          seen.insert(cell);
        }
        EXPECT_EQ(seen.size(), block) << "d " << d << ", level " << level;
      }
    }
  }
}

TEST(SdkSequence, PointsLieInTheSquareAndEvenly) {
  RandomSource random(8);
  SdkSequence sdk(4, random);
  const std::vector<int> counts = gridCounts(16, 4096, [&](double* p) { sdk.next(2, p); });
  const auto [low, high] = std::minmax_element(counts.begin(), counts.end());
  EXPECT_GE(*low, 12);
  EXPECT_LE(*high, 20);
  double wide[4];
  EXPECT_NO_THROW(sdk.next(4, wide));
  EXPECT_THROW(sdk.next(5, wide), std::invalid_argument);
}

TEST(UnitPoints, RandomStreamsReadTheOneSourceInTurn) {
  UnitPoints points(SampleSequence::Random, 42, {3, 2, 1});
  RandomSource reference(42);
  double hand[3], arm[2], step = 0.0;
  points.next(PointStream::Hand, 3, hand);
  points.next(PointStream::SegmentPoint, 1, &step);
  points.next(PointStream::Arm, 2, arm);
  for (const double value : {hand[0], hand[1], hand[2], step, arm[0], arm[1]}) EXPECT_EQ(value, reference.uniform01());
  EXPECT_THROW(points.next(PointStream::Arm, 3, arm), std::invalid_argument);
}

TEST(UnitPoints, HaltonStreamsInStepAreOneHaltonSequence) {
  UnitPoints points(SampleSequence::Halton, 9, {2, 3, 1});
  RandomSource offsets(9);
  HaltonSequence joint(0, 6, offsets);  // hand bases 2, 3; arm 5, 7, 11; segment point 13
  for (int i = 0; i < 20; ++i) {
    double p[6], hand[2], arm[3], step = 0.0;
    joint.next(6, p);
    points.next(PointStream::Hand, 2, hand);
    points.next(PointStream::Arm, 3, arm);
    points.next(PointStream::SegmentPoint, 1, &step);
    EXPECT_EQ(hand[1], p[1]);
    EXPECT_EQ(arm[0], p[2]);
    EXPECT_EQ(step, p[5]);
  }
}

TEST(UnitPoints, TheSameSeedGivesTheSamePointsForEverySequence) {
  for (const SampleSequence s : {SampleSequence::Random, SampleSequence::Halton, SampleSequence::Sdk}) {
    UnitPoints a(s, 11, {5, 6, 1}), b(s, 11, {5, 6, 1}), c(s, 12, {5, 6, 1});
    bool differs = false;
    for (int i = 0; i < 30; ++i) {
      double pa[6], pb[6], pc[6];
      const int d = 2 + i % 4;
      a.next(PointStream::Hand, d, pa);
      b.next(PointStream::Hand, d, pb);
      c.next(PointStream::Hand, d, pc);
      for (int k = 0; k < d; ++k) {
        EXPECT_EQ(pa[k], pb[k]) << sampleSequenceName(s);
        differs = differs || pa[k] != pc[k];
      }
    }
    EXPECT_TRUE(differs) << sampleSequenceName(s) << ": seeds 11 and 12 gave the same points";
  }
}

}  // namespace
}  // namespace pmdplan
