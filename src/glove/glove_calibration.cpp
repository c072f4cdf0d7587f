#include "pmdplan/glove/glove_calibration.hpp"

namespace pmdplan {

Eigen::MatrixXd calibrate(const GloveRecording& recording, const GloveCalibration& calibration) {
  Eigen::MatrixXd angles(recording.frameCount(), kCyberGloveSensorCount);
  for (int f = 0; f < recording.frameCount(); ++f) {
    const GloveFrame& frame = recording.frames[static_cast<std::size_t>(f)];
    for (int s = 0; s < kCyberGloveSensorCount; ++s) {
      const SensorCalibration& sensor = calibration.sensors[static_cast<std::size_t>(s)];
      angles(f, s) = sensor.gain * frame[static_cast<std::size_t>(s)] + sensor.offset;
    }
    for (const CalibrationCrossTerm& term : calibration.crossTerms)
      angles(f, term.sensor) += term.gain * frame[static_cast<std::size_t>(term.from)];
  }
  return angles;
}

}  // namespace pmdplan
