#pragma once
// Per-sensor glove calibration: angle [rad] = gain [rad/count] · raw + offset [rad], plus optional
// cross-coupling terms (a CyberGlove's thumb-roll reading, for instance, picks up thumb abduction,
// and vendor calibrations subtract it). Result: calibrated human joint angles per frame.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "pmdplan/glove/glove_recording.hpp"

namespace pmdplan {

struct SensorCalibration {
  double gain = 0.0;    ///< rad per count
  double offset = 0.0;  ///< rad
};

/// angle[sensor] += gain · raw[from]  (gain in rad per count of `from`).
struct CalibrationCrossTerm {
  int sensor = 0;
  int from = 0;
  double gain = 0.0;
};

struct GloveCalibration {
  /// One entry per sensor, in cyberGloveSensorNames() order.
  std::array<SensorCalibration, kCyberGloveSensorCount> sensors{};
  std::vector<CalibrationCrossTerm> crossTerms;
  /// Free text carried in the file (who calibrated, or that the glove is synthetic).
  std::string description;
};

/// Calibrated angles, one row per frame and one column per sensor (rad).
Eigen::MatrixXd calibrate(const GloveRecording& recording, const GloveCalibration& calibration);

}  // namespace pmdplan
