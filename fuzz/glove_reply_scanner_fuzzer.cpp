// The live glove's reply scanner on arbitrary bytes, fed in pieces whose sizes the input's first
// byte picks: it must never crash, every frame it gives must be a valid reply's (no 0 reading),
// and every byte must be either part of a frame, skipped, or still waiting (fewer than a reply).
#include <cstdlib>

#include "fuzz_input.hpp"
#include "pmdplan/glove/glove_reply_scanner.hpp"
#include "pmdplan/glove/glove_serial_stream.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t piece = 1 + data[0] % 32;
  const std::string_view bytes = pmdplan::fuzz::asText(data + 1, size - 1);
  pmdplan::GloveReplyScanner scanner;
  long long frames = 0;
  for (std::size_t at = 0; at < bytes.size(); at += piece) {
    scanner.feed(bytes.substr(at, piece));
    while (const auto frame = scanner.next()) {
      for (const auto reading : *frame)
        if (reading == 0) std::abort();
      ++frames;
    }
  }
  const long long waiting = static_cast<long long>(bytes.size()) - scanner.offset();
  if (scanner.offset() != frames * pmdplan::kGloveSerialReplyBytes + scanner.skippedBytes()) std::abort();
  if (waiting < 0 || waiting >= pmdplan::kGloveSerialReplyBytes) std::abort();
  return 0;
}
