#pragma once
// CyberGlove recordings as CSV: a header row, an optional `time_s` column, and the 22 raw sensor
// columns named as in cyberGloveSensorNames() (any order), integers 0-255. Lines starting with
// '#' are comments (kept as the recording's notes); blank lines are skipped.
#include <filesystem>
#include <string>
#include <string_view>

#include "pmdplan/glove/glove_recording.hpp"

namespace pmdplan {

/// Reads a recording; throws InputError naming the file, the line and the column on bad input
/// (empty file, unknown or missing column, wrong column count, a cell that is not an integer
/// 0-255, a header without frames).
GloveRecording readGloveCsv(const std::filesystem::path& path);
GloveRecording parseGloveCsv(std::string_view text, const std::string& sourceName);

/// The recording as CSV: notes as '#' lines, a header (with time_s if the recording has times),
/// one row per frame. Reading the text back gives the same recording.
std::string formatGloveCsv(const GloveRecording& recording);

}  // namespace pmdplan
