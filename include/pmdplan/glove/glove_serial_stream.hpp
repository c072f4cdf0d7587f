#pragma once
// The CyberGlove's raw serial replies to the 'G' (get one sample) command, captured to a file:
// each reply is 'G', one byte per sensor (1-255; the glove never sends 0 as a reading), and a
// terminating 0 byte — 24 bytes for the 22-sensor glove. The stream has no times.
#include <filesystem>
#include <string>
#include <string_view>

#include "pmdplan/glove/glove_recording.hpp"

namespace pmdplan {

inline constexpr int kGloveSerialReplyBytes = kCyberGloveSensorCount + 2;

/// Reads a captured stream; throws InputError naming the file, the reply number and its byte
/// offset on a wrong lead byte, a missing terminator, a 0 reading or a truncated last reply.
GloveRecording readGloveSerialStream(const std::filesystem::path& path);
GloveRecording parseGloveSerialStream(std::string_view bytes, const std::string& sourceName);

/// The recording as a stream of 'G' replies. Throws std::invalid_argument if a reading is 0,
/// which the glove's protocol cannot carry.
std::string formatGloveSerialStream(const GloveRecording& recording);

}  // namespace pmdplan
