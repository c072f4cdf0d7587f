#include "pmdplan/glove/cyberglove_sensors.hpp"

#include <string>

namespace pmdplan {

const std::array<std::string_view, kCyberGloveSensorCount>& cyberGloveSensorNames() {
  static const std::array<std::string_view, kCyberGloveSensorCount> names{
      "ThumbRotate", "ThumbMPJ",  "ThumbIJ",       "ThumbAb",  "IndexMPJ",   "IndexPIJ", "IndexDIJ",     "MiddleMPJ",
      "MiddlePIJ",   "MiddleDIJ", "MiddleIndexAb", "RingMPJ",  "RingPIJ",    "RingDIJ",  "RingMiddleAb", "PinkieMPJ",
      "PinkiePIJ",   "PinkieDIJ", "PinkieRingAb",  "PalmArch", "WristPitch", "WristYaw"};
  return names;
}

int cyberGloveSensorIndex(std::string_view name) {
  const auto& names = cyberGloveSensorNames();
  for (int i = 0; i < kCyberGloveSensorCount; ++i)
    if (names[static_cast<std::size_t>(i)] == name) return i;
  return -1;
}

std::string_view cyberGloveSensorList() {
  static const std::string list = [] {
    std::string text;
    for (const auto name : cyberGloveSensorNames()) {
      if (!text.empty()) text += ", ";
      text += name;
    }
    return text;
  }();
  return list;
}

}  // namespace pmdplan
