#include "fuzz_input.hpp"
#include "pmdplan/glove/glove_serial_stream.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pmdplan::fuzz::expectAcceptedOrInputError(
      [&] { pmdplan::parseGloveSerialStream(pmdplan::fuzz::asText(data, size), "fuzz.bin"); });
}
