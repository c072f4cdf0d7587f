#pragma once
// A synthetic glove operator (docs/reference_data.md §4) for the SAH hand: NOT human data. Latent synergies from
// the authors' PMD table drive the 11 glove-driven joints; each latent coordinate is smooth random
// motion (an Ornstein-Uhlenbeck process) mixed with open/close, spread, thumb opposition and pinch
// primitives. The postures are turned back into raw 22-sensor frames through the inverse of the
// hand mapping and a synthetic calibration (which the operator also returns), so the data runs
// through the same read -> calibrate -> map -> PCA path as a real recording.
#include <cstdint>
#include <string>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/glove/glove_calibration.hpp"
#include "pmdplan/glove/glove_recording.hpp"
#include "pmdplan/synergy/hand_mapping.hpp"

namespace pmdplan {

/// The most frames a synthetic recording may have: 10^6 (2.8 h at 100 Hz, about 90 MB of CSV).
inline constexpr int kMaxSyntheticFrames = 1000000;

struct SyntheticOperatorSettings {
  int frames = 13500;  ///< the paper's data set size; 1..kMaxSyntheticFrames
  std::uint64_t seed = 1;
  double sampleRateHz = 100.0;  ///< CyberGlove rate (docs/reference_data.md §3)
  double timeConstantS = 0.8;   ///< correlation time of the smooth random motion (docs/reference_data.md §4)
  /// Total variance of the latent postures, normalised units squared (docs/reference_data.md §4: 0.30-0.35).
  double totalVariance = 0.32;
  /// Share of the time a motion primitive (open/close, spread, opposition, pinch) is under way.
  double primitiveShare = 0.6;
};

struct SyntheticGloveSession {
  GloveRecording recording;      ///< raw frames (1-255) with times and a notice that they are synthetic
  GloveCalibration calibration;  ///< the synthetic glove's calibration, described as synthetic
};

/// The target variance fractions of the latent directions (docs/reference_data.md §4), largest first.
const std::vector<double>& syntheticOperatorVarianceFractions();

/// Throws InputError if the mapping cannot be inverted for the SAH's glove-driven joints (each must
/// be driven by exactly one sensor, and each sensor must drive at most one of them) or a SAH joint
/// is missing from `handJoints`.
SyntheticGloveSession synthesiseGloveSession(const SyntheticOperatorSettings& parameters, const HandMapping& mapping,
                                             const JointLimits& handJoints);

}  // namespace pmdplan
