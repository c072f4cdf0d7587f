#pragma once
// A path as CSV (`--csv`): a header of joint names, then one waypoint per row, values in radians
// (metres for prismatic joints) in their shortest exact form.
#include <filesystem>
#include <string>
#include <vector>

#include "pmdplan/model/configuration.hpp"

namespace pmdplan {

/// Throws std::invalid_argument if a point's size differs from the joint count or a value is not
/// finite. Names holding a comma, a quote or a line break are quoted (RFC 4180).
std::string formatPathCsv(const std::vector<std::string>& jointNames, const std::vector<Configuration>& points);

/// formatPathCsv written atomically.
void writePathCsv(const std::filesystem::path& file, const std::vector<std::string>& jointNames,
                  const std::vector<Configuration>& points);

}  // namespace pmdplan
