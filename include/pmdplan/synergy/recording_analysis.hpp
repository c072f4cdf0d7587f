#pragma once
// The whole path from a glove recording to a synergy model: calibrate, map to the robot's hand
// joints (clamping at the limits), PCA.
#include <string>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/glove/glove_calibration.hpp"
#include "pmdplan/glove/glove_recording.hpp"
#include "pmdplan/synergy/hand_mapping.hpp"
#include "pmdplan/synergy/synergy_fit.hpp"

namespace pmdplan {

struct RecordingAnalysis {
  SynergyFit fit;
  long long clampedValues = 0;
  std::vector<long long> clampedPerJoint;
};

RecordingAnalysis analyseRecording(const GloveRecording& recording, const GloveCalibration& calibration,
                                   const HandMapping& mapping, const JointLimits& handJoints,
                                   const SynergyFitSettings& options, const std::string& provenance);

}  // namespace pmdplan
