#include "pmdplan/synergy/figure7_joint_pairs.hpp"

#include <gtest/gtest.h>

namespace pmdplan {
namespace {

TEST(Figure7JointPairs, TheSixPairsOfThePaper) {
  const auto& pairs = figure7JointPairs();
  ASSERT_EQ(pairs.size(), 6u);
  EXPECT_EQ(pairs[0].first, "middle_proximal");
  EXPECT_EQ(pairs[0].second, "ring_proximal");
  EXPECT_EQ(pairs[3].paper, PaperCorrelation::Negative);
  EXPECT_EQ(pairs[4].paper, PaperCorrelation::Uncorrelated);
}

TEST(Figure7JointPairs, PaperSignsNegateFlexionJoints) {
  for (const char* joint : {"thumb_base", "thumb_proximal", "index_medium", "ring_distal"})
    EXPECT_EQ(paperSignOf(joint), -1.0) << joint;
  for (const char* joint : {"thumb_abduction", "middle_abduction", "ring_abduction"})
    EXPECT_EQ(paperSignOf(joint), 1.0) << joint;
}

}  // namespace
}  // namespace pmdplan
