#pragma once
// 'G' replies (see glove_serial_stream.hpp) picked out of a live byte stream as it arrives: bytes
// come in pieces, a reply may be split across reads, and a line that was opened mid-reply, at the
// wrong baud rate or with noise on it carries bytes that belong to no reply. The scanner skips
// those bytes (counting them) until a valid reply starts: 'G', 22 readings 1-255, a 0 byte.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "pmdplan/glove/cyberglove_sensors.hpp"

namespace pmdplan {

class GloveReplyScanner {
 public:
  /// Appends bytes read from the device.
  void feed(std::string_view bytes);
  /// The next complete, valid reply in what was fed, or nullopt until more bytes arrive. Bytes
  /// before it that are not a valid reply are dropped and counted.
  std::optional<GloveFrame> next();

  /// Bytes dropped in all, and since the last valid reply (or the start).
  long long skippedBytes() const { return skipped_; }
  long long skippedSinceReply() const { return skippedSinceReply_; }
  /// Offset in the stream of the first byte not yet consumed (for messages).
  long long offset() const { return consumed_; }

 private:
  void drop(std::size_t count);

  std::string buffer_;
  long long skipped_ = 0;
  long long skippedSinceReply_ = 0;
  long long consumed_ = 0;
};

}  // namespace pmdplan
