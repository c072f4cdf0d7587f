#pragma once
// Mapping files (YAML), angles in rad:
//   format: pmdplan-hand-mapping
//   version: 1
//   description: "..."
//   joints:
//     - {joint: thumb_base, sensors: {ThumbRotate: 1}}
//     - {joint: thumb_abduction, sensors: {ThumbRotate: -0.3333333333333333}, offset: 0.2617993877991494}
//     - {joint: middle_abduction, constant: 0}
#include <filesystem>
#include <string>
#include <string_view>

#include "pmdplan/synergy/hand_mapping.hpp"

namespace pmdplan {

/// Throws InputError naming the file and line on bad input (unknown sensor name, a rule with both
/// sensors and constant, a joint listed twice, …). Joint names are checked against a robot by
/// rulesForJoints().
HandMapping loadHandMapping(const std::filesystem::path& path);
HandMapping parseHandMapping(std::string_view text, const std::string& sourceName);

/// Text that parses back to exactly the same rules.
std::string formatHandMapping(const HandMapping& mapping);

/// data/glove/cyberglove22_to_sah.yaml, the paper's Table 1.
std::filesystem::path defaultHandMappingPath();

}  // namespace pmdplan
