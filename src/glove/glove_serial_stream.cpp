#include "pmdplan/glove/glove_serial_stream.hpp"

#include <stdexcept>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {
std::string replyField(std::size_t reply, std::size_t byteOffset) {
  return "reply " + std::to_string(reply + 1) + " (byte " + std::to_string(byteOffset) + ")";
}
}  // namespace

GloveRecording parseGloveSerialStream(std::string_view bytes, const std::string& sourceName) {
  constexpr auto replyBytes = static_cast<std::size_t>(kGloveSerialReplyBytes);
  if (bytes.empty())
    throw InputError(
        sourceName, "byte 0",
        "empty stream; expected 'G' replies of " + std::to_string(replyBytes) + " bytes ('G', 22 sensor bytes, 0)");
  GloveRecording recording;
  recording.source = sourceName;
  const std::size_t replies = bytes.size() / replyBytes;
  recording.frames.reserve(replies);
  for (std::size_t r = 0; r * replyBytes < bytes.size(); ++r) {
    const std::size_t start = r * replyBytes;
    if (bytes.size() - start < replyBytes)
      throw InputError(sourceName, replyField(r, start),
                       "truncated reply: " + std::to_string(bytes.size() - start) + " bytes left, expected " +
                           std::to_string(replyBytes));
    if (bytes[start] != 'G')
      throw InputError(
          sourceName, replyField(r, start),
          "a reply must start with 'G' (0x47), found byte " + std::to_string(static_cast<unsigned char>(bytes[start])));
    GloveFrame frame{};
    for (int s = 0; s < kCyberGloveSensorCount; ++s) {
      const auto value = static_cast<unsigned char>(bytes[start + 1 + static_cast<std::size_t>(s)]);
      if (value == 0)
        throw InputError(sourceName, replyField(r, start + 1 + static_cast<std::size_t>(s)),
                         "sensor " + std::string(cyberGloveSensorNames()[static_cast<std::size_t>(s)]) +
                             " reads 0, which the glove never sends (readings are 1-255; 0 ends a reply): "
                             "the stream is out of step or not a 22-sensor 'G' capture");
      frame[static_cast<std::size_t>(s)] = value;
    }
    if (bytes[start + replyBytes - 1] != 0)
      throw InputError(sourceName, replyField(r, start + replyBytes - 1),
                       "a reply must end with a 0 byte after 22 sensor bytes");
    recording.frames.push_back(frame);
  }
  recording.dataLocation = "replies 1-" + std::to_string(recording.frames.size());
  return recording;
}

GloveRecording readGloveSerialStream(const std::filesystem::path& path) {
  return parseGloveSerialStream(readTextFile(path), path.string());
}

std::string formatGloveSerialStream(const GloveRecording& recording) {
  std::string bytes;
  bytes.reserve(recording.frames.size() * static_cast<std::size_t>(kGloveSerialReplyBytes));
  for (const auto& frame : recording.frames) {
    bytes += 'G';
    for (const auto value : frame) {
      if (value == 0) throw std::invalid_argument("a 'G' reply cannot carry a 0 reading");
      bytes += static_cast<char>(value);
    }
    bytes += '\0';
  }
  return bytes;
}

}  // namespace pmdplan
