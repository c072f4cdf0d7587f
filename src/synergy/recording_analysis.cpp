#include "pmdplan/synergy/recording_analysis.hpp"

namespace pmdplan {

RecordingAnalysis analyseRecording(const GloveRecording& recording, const GloveCalibration& calibration,
                                   const HandMapping& mapping, const JointLimits& handJoints,
                                   const SynergyFitSettings& options, const std::string& provenance) {
  const MappedPostures mapped = mapToJoints(calibrate(recording, calibration), mapping, handJoints);
  RecordingAnalysis analysis;
  analysis.clampedValues = mapped.clampedValues;
  analysis.clampedPerJoint = mapped.clampedPerJoint;
  analysis.fit =
      fitSynergyModel(mapped.postures, handJoints, options, {recording.source, recording.dataLocation, provenance});
  return analysis;
}

}  // namespace pmdplan
