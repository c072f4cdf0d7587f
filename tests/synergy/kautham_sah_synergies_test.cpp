#include "pmdplan/synergy/kautham_sah_synergies.hpp"

#include <gtest/gtest.h>

namespace pmdplan {
namespace {

TEST(KauthamSahSynergies, ConvertedToPositiveFlexion) {
  const auto& table = kauthamSahSynergies();
  ASSERT_EQ(table.joints.size(), 13u);
  EXPECT_EQ(table.joints.front(), "thumb_base");
  EXPECT_EQ(table.joints.back(), "ring_medium");
  // Flexion joints: p = 1 - p_kautham; abduction joints keep p.
  EXPECT_NEAR(table.mean(0), 1 - 0.3055, 1e-12);  // thumb_base
  EXPECT_NEAR(table.mean(1), 0.3055, 1e-12);      // thumb_abduction
  EXPECT_NEAR(table.mean(8), 1 - 0.5579, 1e-12);  // middle_proximal
  EXPECT_NEAR(table.mean(7), 0.5, 1e-12);         // middle_abduction
  // Components: negated on flexion joints, kept on abduction joints (up to the renormalisation).
  const double scale = table.directions(4, 0) / 0.2409;
  EXPECT_NEAR(scale, 1.0, 2e-3);
  EXPECT_NEAR(table.directions(8, 0), 0.4884 * scale, 1e-12);
  EXPECT_NEAR(table.directions(10, 0), -0.1741 * scale, 1e-12);
}

TEST(KauthamSahSynergies, UnitVectorsZeroOnThumbBaseAndMiddleAbduction) {
  const auto& table = kauthamSahSynergies();
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(table.directions.col(k).norm(), 1.0, 1e-12);
    EXPECT_EQ(table.directions(0, k), 0.0);
    EXPECT_EQ(table.directions(7, k), 0.0);
  }
  // The published vectors are orthonormal to their four decimals.
  const Eigen::MatrixXd gram = table.directions.transpose() * table.directions;
  EXPECT_TRUE(gram.isIdentity(2e-3));
}

}  // namespace
}  // namespace pmdplan
