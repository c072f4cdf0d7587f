#pragma once
// The 22 sensors of the CyberGlove, in the order the glove sends them (docs/reference_data.md §3). Recordings,
// calibrations and mappings name sensors by these column names.
#include <array>
#include <cstdint>
#include <string_view>

namespace pmdplan {

inline constexpr int kCyberGloveSensorCount = 22;

/// One raw reading per sensor (the glove sends one unsigned byte per sensor).
using GloveFrame = std::array<std::uint8_t, kCyberGloveSensorCount>;

/// Column names in the glove's order: ThumbRotate, ThumbMPJ, …, WristPitch, WristYaw.
const std::array<std::string_view, kCyberGloveSensorCount>& cyberGloveSensorNames();

/// Index of a sensor by its column name, or -1.
int cyberGloveSensorIndex(std::string_view name);

/// "ThumbRotate, ThumbMPJ, …" for error messages that list what is expected.
std::string_view cyberGloveSensorList();

}  // namespace pmdplan
