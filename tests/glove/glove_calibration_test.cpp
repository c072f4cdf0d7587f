#include "pmdplan/glove/glove_calibration.hpp"

#include <gtest/gtest.h>

namespace pmdplan {
namespace {

TEST(GloveCalibration, GainTimesRawPlusOffsetPlusCrossTerms) {
  GloveRecording recording;
  GloveFrame frame{};
  frame[0] = 100;
  frame[3] = 40;
  frame[4] = 200;
  recording.frames = {frame, GloveFrame{}};
  GloveCalibration calibration;
  calibration.sensors[0] = {0.01, -0.5};
  calibration.sensors[3] = {0.02, 0.1};
  calibration.sensors[4] = {-0.005, 1.0};
  calibration.crossTerms.push_back({0, 3, -0.001});
  const Eigen::MatrixXd angles = calibrate(recording, calibration);
  ASSERT_EQ(angles.rows(), 2);
  ASSERT_EQ(angles.cols(), kCyberGloveSensorCount);
  EXPECT_DOUBLE_EQ(angles(0, 0), 0.01 * 100 - 0.5 - 0.001 * 40);
  EXPECT_DOUBLE_EQ(angles(0, 3), 0.02 * 40 + 0.1);
  EXPECT_DOUBLE_EQ(angles(0, 4), -0.005 * 200 + 1.0);
  EXPECT_DOUBLE_EQ(angles(1, 0), -0.5);
  EXPECT_DOUBLE_EQ(angles(1, 5), 0.0);
}

}  // namespace
}  // namespace pmdplan
