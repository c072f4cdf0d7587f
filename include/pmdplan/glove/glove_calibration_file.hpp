#pragma once
// Calibration files (YAML):
//   format: pmdplan-glove-calibration
//   version: 1
//   description: "..."
//   sensors:            # every one of the 22 sensors, gain in rad per count, offset in rad
//     ThumbRotate: {gain: 0.0061, offset: -0.52}
//     ...
//   cross_terms:        # optional: angle[sensor] += gain * raw[from]
//     - {sensor: ThumbRotate, from: ThumbAb, gain: -0.0006}
#include <filesystem>
#include <string>
#include <string_view>

#include "pmdplan/glove/glove_calibration.hpp"

namespace pmdplan {

/// Throws InputError naming the file, the line and the key on bad input.
GloveCalibration loadGloveCalibration(const std::filesystem::path& path);
GloveCalibration parseGloveCalibration(std::string_view text, const std::string& sourceName);

/// Text that parses back to exactly the same values (shortest round-trip number form).
std::string formatGloveCalibration(const GloveCalibration& calibration);

}  // namespace pmdplan
