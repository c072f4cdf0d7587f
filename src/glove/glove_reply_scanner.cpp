#include "pmdplan/glove/glove_reply_scanner.hpp"

#include "pmdplan/glove/glove_serial_stream.hpp"

namespace pmdplan {

void GloveReplyScanner::feed(std::string_view bytes) { buffer_.append(bytes); }

void GloveReplyScanner::drop(std::size_t count) {
  buffer_.erase(0, count);
  consumed_ += static_cast<long long>(count);
}

std::optional<GloveFrame> GloveReplyScanner::next() {
  constexpr auto replyBytes = static_cast<std::size_t>(kGloveSerialReplyBytes);
  for (;;) {
    const std::size_t lead = buffer_.find('G');
    const std::size_t garbage = lead == std::string::npos ? buffer_.size() : lead;
    if (garbage > 0) {
      skipped_ += static_cast<long long>(garbage);
      skippedSinceReply_ += static_cast<long long>(garbage);
      drop(garbage);
    }
    if (buffer_.size() < replyBytes) return std::nullopt;
    bool valid = buffer_[replyBytes - 1] == '\0';
    for (std::size_t s = 1; valid && s <= static_cast<std::size_t>(kCyberGloveSensorCount); ++s)
      valid = buffer_[s] != '\0';
    if (!valid) {
      // Not a reply after all: this 'G' was a reading or noise; look for the next one.
      ++skipped_;
      ++skippedSinceReply_;
      drop(1);
      continue;
    }
    GloveFrame frame{};
    for (std::size_t s = 0; s < frame.size(); ++s) frame[s] = static_cast<std::uint8_t>(buffer_[s + 1]);
    drop(replyBytes);
    skippedSinceReply_ = 0;
    return frame;
  }
}

}  // namespace pmdplan
