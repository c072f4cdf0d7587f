#include "pmdplan/synergy/kautham_sah_synergies.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(KauthamSahSynergies, NormalisedOverKauthamsLimitsInOurSigns) {
  const auto& table = kauthamSahSynergies();
  ASSERT_EQ(table.limits.size(), table.joints.size());
  const double degree = M_PI / 180.0;
  for (std::size_t j = 0; j < table.joints.size(); ++j) EXPECT_EQ(table.limits[j].name, table.joints[j]);
  EXPECT_NEAR(table.limits[0].upper, 90 * degree, 1e-12);   // thumb_base 0..90
  EXPECT_NEAR(table.limits[1].lower, -15 * degree, 1e-12);  // thumb_abduction -15..15
  EXPECT_NEAR(table.limits[2].lower, -4 * degree, 1e-12);   // thumb_proximal -4..75
  EXPECT_NEAR(table.limits[3].lower, 4 * degree, 1e-12);    // thumb_medium 4..75
  EXPECT_NEAR(table.limits[12].upper, 75 * degree, 1e-12);  // ring_medium
  // Kautham's p = 0 is a flexion joint's flexed end, ours its extended end (p = 1 - p_K).
  EXPECT_NEAR(table.limits[8].denormalise(table.mean(8)), (-4 + (1 - 0.5579) * 79) * degree, 1e-12);
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
